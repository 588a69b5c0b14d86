// The board's status lines (rtl/board/status_line.sv) as data, and in words.
// Idea: the board sends fixed-layout hex lines ("B 0000C 1E240 FFC18"), cheap in hardware;
// the host parses them here and shows them in mm and in the project's error messages, so
// `ncinterp send`, the board simulation and the tests read them one way. The layout, the
// link's special bytes and the board's error codes are the ones of
// sw/host/tape/board_link.def, which the RTL's constants come from too.
#pragma once
#include <cstdint>
#include <optional>
#include <string>

namespace ncinterp::board {

#define BOARD_LINK_BYTE(name, byte, meaning) inline constexpr uint8_t kLink##name = byte;
#define BOARD_ERROR(name, code, message)
#define BOARD_STATUS(name, letter, meaning) inline constexpr char kStatus##name = letter;
#define BOARD_STATUS_DIGITS(n) inline constexpr unsigned kStatusDigits = n;
#include "board_link.def"
#undef BOARD_LINK_BYTE
#undef BOARD_ERROR
#undef BOARD_STATUS
#undef BOARD_STATUS_DIGITS

// Board-level error codes (above the interpolator's TapeError codes).
enum class BoardError : uint8_t {
#define BOARD_LINK_BYTE(name, byte, meaning)
#define BOARD_ERROR(name, code, message) k##name = code,
#define BOARD_STATUS(name, letter, meaning)
#define BOARD_STATUS_DIGITS(n)
#include "board_link.def"
#undef BOARD_LINK_BYTE
#undef BOARD_ERROR
#undef BOARD_STATUS
#undef BOARD_STATUS_DIGITS
};

struct StatusLine {
  char kind = 0;         // kStatusBlock, kStatusDone or kStatusError
  uint8_t code = 0;      // error code (kStatusError)
  uint32_t block = 0;    // N
  int64_t x = 0, y = 0;  // position, BLU (kStatusBlock, kStatusDone)
  uint32_t offset = 0;   // frame offset (kStatusError), modulo 16^kStatusDigits
};

// A line without its CR LF; nullopt when it is not a status line.
std::optional<StatusLine> parse_status_line(const std::string& line);

// The message of an error code: the interpolator's tape errors and the board's own.
std::string board_error_message(uint8_t code);

// In words: "block N12 ended at X1.234 Y-0.500 mm", "error in block N3 at offset 57: ...".
std::string describe(const StatusLine& s, unsigned frac_digits);

}  // namespace ncinterp::board
