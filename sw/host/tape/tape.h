// Tape format v1 (docs/tape-format.md): blocks <-> ISO 6983 word-address text <-> 8-bit
// frames with ISO 840 even parity.
// Idea: the first stage builds a Program of integer blocks (BLU, feed units) and writes it;
// tests, the checker and reports read a tape back into the same Program. The software
// reader enforces the same rules as the hardware decoder, so a tape it accepts plays.
#pragma once
#include <cstdint>
#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

#include "tape_errors.h"

namespace ncinterp::tape {

// G00, G01, G02, G03 (tape_motions.def: the code is the G number).
enum class Motion : uint8_t {
#define TAPE_MOTION(name, code, word) k##name = code,
#include "tape_motions.def"
#undef TAPE_MOTION
};
// G02/G03: played by the circle DDA, checked by the arc rules.
constexpr bool is_arc(Motion m) { return m == Motion::kArcCw || m == Motion::kArcCcw; }
// G00: a traverse, not a cut; it needs no F and plays at the machine's rapid rate.
constexpr bool is_rapid(Motion m) { return m == Motion::kRapid; }
// "G00", "G01", "G02", "G03".
const char* motion_word(Motion m);

// A G number that is a motion (tape_motions.def).
constexpr bool is_motion(uint64_t g) {
#define TAPE_MOTION(name, code, word) \
  if (g == code) return true;
#include "tape_motions.def"
#undef TAPE_MOTION
  return false;
}

// What the interpolator does with a G or M code that is not a motion (tape_codes.def).
enum class CodeKind : uint8_t {
  kUnsupported, kSetting, kEnd, kStop, kOptionalStop, kToolOn, kToolOff
};
constexpr CodeKind code_kind(char letter, uint64_t number) {
#define TAPE_CODE(l, n, kind, meaning) \
  if (letter == #l[0] && number == n) return CodeKind::k##kind;
#include "tape_codes.def"
#undef TAPE_CODE
  return CodeKind::kUnsupported;
}

struct Block {
  uint32_t n = 0;               // sequence number
  Motion motion = Motion::kLine;
  int64_t dx = 0, dy = 0;       // incremental move, BLU
  int64_t i = 0, j = 0;         // arc centre relative to the block's start, BLU
  uint64_t feed = 0;            // inverse time, units of 10^-feed_frac_digits 1/min;
                                // 0 for a G00 block (it plays at the rapid rate)
  // The block's M word, if it is one of these (block_record.def; at most one is set): M00
  // and M01 pause after the block, M03 switches the tool on as it starts, M05 off as it ends.
  bool stop = false, optional_stop = false, tool_on = false, tool_off = false;
  // No motion word, only an M word: played as a G00 of length 0 (motion kRapid, dx = dy =
  // 0), written back without X and Y.
  bool still = false;
};

struct Format {
  unsigned frac_digits = 3;       // BLU = 10^-frac_digits mm
  unsigned feed_frac_digits = 3;  // fraction digits of F
  unsigned inc_width = 16;        // |dx|,|dy|,|i|,|j| <= 2^inc_width - 1
  // Added after v1's first draft; the defaults are the interpolator's (InterpConfig).
  unsigned feed_width = 32;       // F <= 2^feed_width - 1
  unsigned seq_width = 20;        // N <= 2^seq_width - 1
  // The interpolator plays G02/G03 (circle mode); without it an arc's G word is refused
  // (TapeError::kNoCircleMode), as the lines-only interpolator refuses it.
  bool circle_mode = true;
  // The interpolator plays M00, M01, M03 and M05; without them (the iCEstick's) each is
  // refused (TapeError::kUnsupportedCode), as its decoder refuses it.
  bool misc_functions = true;
};

struct Program {
  std::vector<Block> blocks;  // motion and still blocks in tape order
  bool end_m30 = false;       // end block is M30 (else M02)
};

// Where and why a tape is bad: the block's N (or the previous N when the bad block has
// none yet) and the 0-based offset of the offending frame.
struct TapeErrorInfo {
  uint32_t block = 0;
  uint64_t offset = 0;
  std::string message;
  unsigned code = 0;  // the interpolator's error code (ncinterp::TapeError, tape_errors.h)
};

class TapeFormatError : public std::runtime_error {
 public:
  explicit TapeFormatError(TapeErrorInfo info);
  const TapeErrorInfo& info() const { return info_; }

 private:
  TapeErrorInfo info_;
};

// "block N<n>, offset K: message": the part of the one-line error after "FILE: ".
std::string describe(const TapeErrorInfo& info);

// Program -> tape text ("%\n" setup block, motion blocks, M02, "%\n").
std::string format_program(const Program& program, const Format& format);
// Adds ISO 840 even parity in bit 7 of every 7-bit character.
std::vector<uint8_t> add_parity(std::string_view text);
// Frames -> Program; throws TapeFormatError on any rule the decoder enforces.
Program parse_frames(const std::vector<uint8_t>& frames, const Format& format);
// Frames -> every block before the first error, and that error (if any). What a machine
// plays of a bad tape: the system model's monitors use it to know the programmed chords.
struct ParseResult {
  Program program;
  std::optional<TapeErrorInfo> error;
};
ParseResult parse_frames_partial(const std::vector<uint8_t>& frames, const Format& format);
// True when the frame has an even number of ones (ISO 840).
bool has_even_parity(uint8_t frame);
// A .tape file holds the frames as punched; any other is plain text.
bool is_frame_file(const std::string& path);
// Reads a tape file: .tape files are frames as they are; any other file (.nc, .ngc, .txt)
// is plain text and gets parity added. Throws std::runtime_error naming the file.
std::vector<uint8_t> load_frames(const std::string& path);
// Writes the program atomically (temporary file + rename): no half-written tape on failure.
// A .tape path gets frames with parity; any other extension gets the plain text. Throws
// std::invalid_argument (a value the format cannot hold) before touching the file system.
void write_tape_file(const std::string& path, const Program& program, const Format& format);

}  // namespace ncinterp::tape
