// The board's status lines (rtl/board/status_line.sv) as data, and in words.
// Idea: the board sends fixed-layout hex lines ("B 00 0000C 0001F400 FFFFF600"), cheap in
// hardware; the host parses them here and shows them in mm and in the project's error
// messages, so `ncinterp send`, the board simulation and the tests read them one way.
#pragma once
#include <cstdint>
#include <optional>
#include <string>

namespace ncinterp::board {

// Board-level error codes (above the interpolator's 4-bit TapeError codes).
enum class BoardError : uint8_t { kFifoOverflow = 0x10, kFraming = 0x11, kStepOverrun = 0x12 };

struct StatusLine {
  char kind = 0;       // 'B' block ended, 'D' program done, 'E' error
  uint8_t code = 0;    // error code ('E')
  uint32_t block = 0;  // N
  int64_t x = 0, y = 0;  // position, BLU ('B', 'D')
  uint32_t offset = 0;   // frame offset ('E')
};

// A line without its CR LF; nullopt when it is not a status line.
std::optional<StatusLine> parse_status_line(const std::string& line);

// The message of an error code: the interpolator's tape errors and the board's own.
std::string board_error_message(uint8_t code);

// In words: "block N12 ended at X1.234 Y-0.500 mm", "error in block N3 at offset 57: ...".
std::string describe(const StatusLine& s, unsigned frac_digits);

// The EOT frame that ends the tape (EOT, 0x04, with its ISO 840 parity bit).
inline constexpr uint8_t kEndOfTapeFrame = 0x84;
inline constexpr uint8_t kXon = 0x11, kXoff = 0x13;

}  // namespace ncinterp::board
