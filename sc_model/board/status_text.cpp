// Parsing and wording of the board's status lines (see status_text.h).
#include "status_text.h"

#include <cmath>
#include <cstdio>
#include <cstdlib>

#include "interp_ports.h"

namespace ncinterp::board {
namespace {

bool hex_field(const std::string& s, size_t pos, size_t len, uint64_t& value) {
  if (pos + len > s.size()) return false;
  value = 0;
  for (size_t i = pos; i < pos + len; ++i) {
    const char c = s[i];
    const int d = c >= '0' && c <= '9' ? c - '0' : c >= 'A' && c <= 'F' ? c - 'A' + 10 : -1;
    if (d < 0) return false;
    value = value * 16 + static_cast<uint64_t>(d);
  }
  return true;
}

std::string mm(int64_t blu, unsigned frac_digits) {
  char buf[48];
  std::snprintf(buf, sizeof buf, "%.*f", static_cast<int>(frac_digits),
                static_cast<double>(blu) / std::pow(10.0, frac_digits));
  return buf;
}

}  // namespace

std::optional<StatusLine> parse_status_line(const std::string& line) {
  // "K CC NNNNN AAAAAAAA BBBBBBBB"
  if (line.size() != 28 || line[1] != ' ' || line[4] != ' ' || line[10] != ' ' || line[19] != ' ')
    return std::nullopt;
  StatusLine s;
  s.kind = line[0];
  if (s.kind != 'B' && s.kind != 'D' && s.kind != 'E') return std::nullopt;
  uint64_t code, n, a, b;
  if (!hex_field(line, 2, 2, code) || !hex_field(line, 5, 5, n) || !hex_field(line, 11, 8, a) ||
      !hex_field(line, 20, 8, b))
    return std::nullopt;
  s.code = static_cast<uint8_t>(code);
  s.block = static_cast<uint32_t>(n);
  if (s.kind == 'E') {
    s.offset = static_cast<uint32_t>(a);
  } else {
    s.x = static_cast<int32_t>(static_cast<uint32_t>(a));
    s.y = static_cast<int32_t>(static_cast<uint32_t>(b));
  }
  return s;
}

std::string board_error_message(uint8_t code) {
  switch (static_cast<BoardError>(code)) {
    case BoardError::kFifoOverflow: return "the board's tape FIFO overflowed (flow control failed)";
    case BoardError::kFraming: return "UART framing error (wrong baud rate or a broken line)";
    case BoardError::kStepOverrun:
      return "a step pulse was lost: steps came faster than the driver timing allows";
  }
  return tape_error_message(static_cast<TapeError>(code));
}

std::string describe(const StatusLine& s, unsigned frac_digits) {
  const std::string n = "N" + std::to_string(s.block);
  if (s.kind == 'E')
    return "error in block " + n + " at offset " + std::to_string(s.offset) + ": " +
           board_error_message(s.code) + " (code " + std::to_string(s.code) + ")";
  const std::string pos = "X" + mm(s.x, frac_digits) + " Y" + mm(s.y, frac_digits) + " mm";
  return s.kind == 'D' ? "program done after block " + n + " at " + pos
                       : "block " + n + " ended at " + pos;
}

}  // namespace ncinterp::board
