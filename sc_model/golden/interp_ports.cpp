// Messages for the interpolator's error codes (interp_ports.h), shared by every report.
#include "interp_ports.h"

namespace ncinterp {

const char* tape_error_message(TapeError code) {
  switch (code) {
    case TapeError::kNone: return "no error";
    case TapeError::kParity: return "parity error";
    case TapeError::kUnknownCharacter: return "unknown address letter or character";
    case TapeError::kMalformedNumber: return "malformed number";
    case TapeError::kValueTooWide: return "value too wide for its register";
    case TapeError::kMissingEndOfBlock: return "missing end of block";
    case TapeError::kUnsupportedCode: return "unsupported G or M code";
    case TapeError::kTruncatedTape: return "truncated tape (tape ended before M02/M30)";
    case TapeError::kBlockAfterEnd: return "block after end of program";
    case TapeError::kMissingFeed: return "missing feed (no F programmed, or F0)";
    case TapeError::kArcCrossesQuadrant: return "arc not inside one quadrant";
    case TapeError::kArcEndpointOffCircle: return "arc endpoint off its circle";
    case TapeError::kArcZeroRadius: return "zero-radius arc";
  }
  return "unknown error code";
}

}  // namespace ncinterp
