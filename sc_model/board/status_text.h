// The board's status lines (rtl/board/status_line.sv) as data, resolved, and in words.
// Idea: the board sends fixed-layout lines of nibble digits ("B0<>24<18": N 0x0C, X 0xE24,
// Y 0xC18), cheap in hardware: a kind letter, N modulo 16^kStatusBlockDigits, and two
// fields of kStatusDigits digits (X and Y, or the frame offset and the error code), each
// the low bits of its value. The host sent the tape and reads every line in order, so it
// resolves them (StatusTracker): a position by continuity from 0 (a line goes out every
// line time while the machine moves, and an axis moves less than half the field's range,
// 2048 BLU, in one: at most some 250 steps at 115 200 baud, the step stretchers' top
// rate), N as the next of the tape's blocks with those low bits, an offset as the last
// frame sent with those low bits (exact while fewer than 4096 frames are between the
// host's count and the board's; `send` names a tape error by the software reader's own
// place when it agrees with the line's low bits). `ncinterp send`, the board simulation and the tests read the lines
// one way. The layout, the link's special bytes and the board's error codes are the ones
// of sw/host/tape/board_link.def, which the RTL's constants come from too.
#pragma once
#include <cstdint>
#include <iterator>
#include <optional>
#include <string>
#include <vector>

#include "tape.h"

namespace ncinterp::board {

#define BOARD_LINK_BYTE(name, byte, meaning) inline constexpr uint8_t kLink##name = byte;
#define BOARD_LINK_COUNT(name, value, meaning) inline constexpr unsigned kLink##name = value;
#define BOARD_STATUS(name, letter, meaning) inline constexpr char kStatus##name = letter;
#define BOARD_STATUS_DIGITS(block, field)                          \
  inline constexpr unsigned kStatusBlockDigits = block;            \
  inline constexpr unsigned kStatusDigits = field;
#include "board_link.def"

// The realtime commands in the list's order (the bit of interp_pkg::realtime_command()
// and of operator_pins' remote_i).
struct RealtimeCommand {
  const char* name;
  uint8_t byte;
  char key;  // `send`'s key for it
  const char* meaning;
};
inline constexpr RealtimeCommand kRealtimeCommands[] = {
#define BOARD_REALTIME(name, byte, key, meaning) {#name, byte, key, meaning},
#include "board_link.def"
};
inline constexpr int kRealtimeCommandCount = static_cast<int>(std::size(kRealtimeCommands));

// Board-level error codes (above the interpolator's TapeError codes).
enum class BoardError : uint8_t {
#define BOARD_ERROR(name, code, message) k##name = code,
#include "board_link.def"
};

// A board error's code is none of the interpolator's: both go out in the E line's code.
constexpr bool board_errors_above_tape_errors() {
#define BOARD_ERROR(name, code, message) \
  if ((code) < (1u << kTapeErrorBits) || (code) > 0xff) return false;
#include "board_link.def"
  return true;
}
static_assert(board_errors_above_tape_errors(), "board_link.def: a board error code collides with a tape error's");

// A line as the board sends it: each field the low bits of its value.
struct StatusLine {
  char kind = 0;           // kStatusBlock, kStatusDone or kStatusError
  uint32_t block = 0;      // N modulo 16^kStatusBlockDigits
  uint32_t x = 0, y = 0;   // position modulo 16^kStatusDigits (two's complement; B, D)
  uint32_t offset = 0;     // frame offset modulo 16^kStatusDigits (E)
  uint8_t code = 0;        // error code (E)
};

// A line without its CR LF; nullopt when it is not a status line.
std::optional<StatusLine> parse_status_line(const std::string& line);

// What a line says, resolved.
struct BoardStatus {
  char kind = 0;
  uint32_t block = 0;    // N
  int64_t x = 0, y = 0;  // position, BLU (B, D)
  uint64_t offset = 0;   // frame offset (E)
  uint8_t code = 0;      // error code (E)
};

// Resolves the lines of one run of the board (from its reset) in the order it sent them.
class StatusTracker {
 public:
  // program: the tape's motion blocks (those the board plays, in order; their N).
  explicit StatusTracker(const tape::Program& program);
  // frames_sent: how many frames the host has sent so far (an error's offset is below).
  BoardStatus resolve(const StatusLine& line, uint64_t frames_sent);

 private:
  std::vector<uint32_t> ns_;  // the motion blocks' N
  size_t next_ = 0;           // the first block the next line may name
  bool seen_ = false;         // a block has been named
  uint32_t last_n_ = 0;       // the last N named
  int64_t x_ = 0, y_ = 0;     // the last position
};

// The message of an error code: the interpolator's tape errors and the board's own.
std::string board_error_message(uint8_t code);

// In words: "block N12 playing, at X1.234 Y-0.500 mm", "program done after block N48 at
// ...", "error in block N3 at offset 57: parity error (code 1)".
std::string describe(const BoardStatus& s, unsigned frac_digits);

}  // namespace ncinterp::board
