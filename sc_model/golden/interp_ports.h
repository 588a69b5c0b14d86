// Ports and parameters of the interpolator, shared by the golden model, the verilated RTL
// wrappers, the SystemC system model and the lock-step scoreboard.
// Idea: the RTL (rtl/interp_top.sv) and GoldenInterp have exactly these inputs and outputs;
// the field names follow the RTL port names without the _i/_o suffix, so a mismatch
// report and a VCD name the same signal in both implementations. docs/architecture.md
// explains each field.
#pragma once
#include <cstdint>

namespace ncinterp {

// Elaboration parameters (RTL parameters of the same name) plus the static configuration
// input feed_modulus_i, which depends on the clock frequency.
struct InterpConfig {
  unsigned inc_width = 16;        // IncWidth (W)
  unsigned frac_digits = 3;       // FracDigits: BLU = 10^-frac_digits mm
  unsigned feed_width = 32;       // FeedWidth
  unsigned feed_frac_digits = 3;  // FeedFracDigits
  unsigned pos_width = 32;        // PosWidth
  unsigned seq_width = 20;        // SeqWidth
  unsigned offset_width = 32;     // OffsetWidth
  unsigned modulus_width = 48;    // ModulusWidth
  // feed_modulus_i = 60 * clock_hz * 10^feed_frac_digits.
  uint64_t feed_modulus = 60ull * 1000000ull * 1000ull;

  static uint64_t feed_modulus_for(double clock_hz, unsigned feed_frac_digits) {
    uint64_t scale = 1;
    for (unsigned i = 0; i < feed_frac_digits; ++i) scale *= 10;
    return static_cast<uint64_t>(60.0 * clock_hz + 0.5) * scale;
  }
};

struct InterpInputs {
  uint8_t frame = 0;
  bool frame_valid = false;
  bool tape_end = false;
};

enum class TapeError : uint8_t {
  kNone = 0,
  kParity = 1,
  kUnknownCharacter = 2,
  kMalformedNumber = 3,
  kValueTooWide = 4,
  kMissingEndOfBlock = 5,
  kUnsupportedCode = 6,
  kTruncatedTape = 7,
  kBlockAfterEnd = 8,
  kMissingFeed = 9,
  kArcCrossesQuadrant = 10,
  kArcEndpointOffCircle = 11,
  kArcZeroRadius = 12,
};

const char* tape_error_message(TapeError code);

struct InterpOutputs {
  bool frame_ready = false;
  bool step_x = false;
  bool dir_x = false;
  bool step_y = false;
  bool dir_y = false;
  int64_t pos_x = 0;  // sign-extended from pos_width bits
  int64_t pos_y = 0;
  uint32_t block_n = 0;
  bool busy = false;
  bool done = false;
  bool error = false;
  uint8_t error_code = 0;
  uint32_t error_block = 0;
  uint32_t error_offset = 0;
  bool feed_saturated = false;

  bool operator==(const InterpOutputs& o) const {
    return frame_ready == o.frame_ready && step_x == o.step_x && dir_x == o.dir_x &&
           step_y == o.step_y && dir_y == o.dir_y && pos_x == o.pos_x && pos_y == o.pos_y &&
           block_n == o.block_n && busy == o.busy && done == o.done && error == o.error &&
           error_code == o.error_code && error_block == o.error_block &&
           error_offset == o.error_offset && feed_saturated == o.feed_saturated;
  }
  bool operator!=(const InterpOutputs& o) const { return !(*this == o); }
};

}  // namespace ncinterp
