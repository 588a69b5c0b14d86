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
  // "K AAAAA BBBBB CCCCC": a kind letter, then three fields of kStatusDigits hex digits.
  constexpr size_t field = 1 + kStatusDigits;
  if (line.size() != 1 + 3 * field) return std::nullopt;
  StatusLine s;
  s.kind = line[0];
  if (s.kind != kStatusBlock && s.kind != kStatusDone && s.kind != kStatusError) return std::nullopt;
  uint64_t f[3];
  for (size_t i = 0; i < 3; ++i)
    if (line[1 + i * field] != ' ' || !hex_field(line, 2 + i * field, kStatusDigits, f[i])) return std::nullopt;
  // A position field is two's complement in its 4 * kStatusDigits bits.
  const auto position = [](uint64_t v) {
    const uint64_t sign = uint64_t{1} << (4 * kStatusDigits - 1);
    return static_cast<int64_t>((v ^ sign) - sign);
  };
  s.block = static_cast<uint32_t>(f[0]);
  if (s.kind == kStatusError) {
    s.offset = static_cast<uint32_t>(f[1]);
    if (f[2] > 0xff) return std::nullopt;
    s.code = static_cast<uint8_t>(f[2]);
  } else {
    s.x = position(f[1]);
    s.y = position(f[2]);
  }
  return s;
}

std::string board_error_message(uint8_t code) {
  switch (code) {
#define BOARD_LINK_BYTE(name, byte, meaning)
#define BOARD_ERROR(name, code, message) \
  case code:                             \
    return message;
#define BOARD_STATUS(name, letter, meaning)
#define BOARD_STATUS_DIGITS(n)
#include "board_link.def"
#undef BOARD_LINK_BYTE
#undef BOARD_ERROR
#undef BOARD_STATUS
#undef BOARD_STATUS_DIGITS
  }
  return tape_error_message(static_cast<TapeError>(code));
}

std::string describe(const StatusLine& s, unsigned frac_digits) {
  const std::string n = "N" + std::to_string(s.block);
  if (s.kind == kStatusError)
    return "error in block " + n + " at offset " + std::to_string(s.offset) + ": " +
           board_error_message(s.code) + " (code " + std::to_string(s.code) + ")";
  const std::string pos = "X" + mm(s.x, frac_digits) + " Y" + mm(s.y, frac_digits) + " mm";
  return s.kind == kStatusDone ? "program done after block " + n + " at " + pos
                       : "block " + n + " ended at " + pos;
}

}  // namespace ncinterp::board
