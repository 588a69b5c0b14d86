// Parsing, resolving and wording of the board's status lines (see status_text.h).
#include "status_text.h"

#include <cmath>
#include <cstdio>
#include <cstdlib>

#include "interp_ports.h"

namespace ncinterp::board {
namespace {

// A field of `len` nibble digits, each the character 0x30 + nibble.
bool nibble_field(const std::string& s, size_t pos, size_t len, uint32_t& value) {
  if (pos + len > s.size()) return false;
  value = 0;
  for (size_t i = pos; i < pos + len; ++i) {
    const unsigned char c = static_cast<unsigned char>(s[i]);
    if (c < 0x30 || c > 0x3f) return false;
    value = value * 16 + (c - 0x30u);
  }
  return true;
}

std::string mm(int64_t blu, unsigned frac_digits) {
  char buf[48];
  std::snprintf(buf, sizeof buf, "%.*f", static_cast<int>(frac_digits),
                static_cast<double>(blu) / std::pow(10.0, frac_digits));
  return buf;
}

constexpr uint64_t kBlockRange = uint64_t{1} << (4 * kStatusBlockDigits);
constexpr uint64_t kFieldRange = uint64_t{1} << (4 * kStatusDigits);

// The value nearest `last` with these low bits (a field of `range` values).
int64_t unwrap(int64_t last, uint32_t low, uint64_t range) {
  const uint64_t delta = (static_cast<uint64_t>(low) - static_cast<uint64_t>(last)) & (range - 1);
  return last + (delta >= range / 2 ? static_cast<int64_t>(delta) - static_cast<int64_t>(range)
                                    : static_cast<int64_t>(delta));
}

}  // namespace

std::optional<StatusLine> parse_status_line(const std::string& line) {
  // "KAABBBBCCCC": a kind letter, the block field, two fields.
  if (line.size() != 1 + kStatusBlockDigits + 2 * kStatusDigits) return std::nullopt;
  StatusLine s;
  s.kind = line[0];
  if (s.kind != kStatusBlock && s.kind != kStatusDone && s.kind != kStatusError) return std::nullopt;
  uint32_t b = 0, c = 0;
  if (!nibble_field(line, 1, kStatusBlockDigits, s.block) ||
      !nibble_field(line, 1 + kStatusBlockDigits, kStatusDigits, b) ||
      !nibble_field(line, 1 + kStatusBlockDigits + kStatusDigits, kStatusDigits, c))
    return std::nullopt;
  if (s.kind == kStatusError) {
    if (c > 0xff) return std::nullopt;
    s.offset = b;
    s.code = static_cast<uint8_t>(c);
  } else {
    s.x = b;
    s.y = c;
  }
  return s;
}

StatusTracker::StatusTracker(const tape::Program& program) {
  for (const tape::Block& b : program.blocks) ns_.push_back(b.n);
}

BoardStatus StatusTracker::resolve(const StatusLine& line, uint64_t frames_sent) {
  BoardStatus s;
  s.kind = line.kind;
  s.code = line.code;
  // N: the next block of the tape (from the last one named) with these low bits; else (a
  // block the tape's motion blocks do not have, such as a bad one) the nearest N at or
  // above the last one named.
  size_t j = next_;
  while (j < ns_.size() && ns_[j] % kBlockRange != line.block) ++j;
  if (j < ns_.size()) {
    s.block = ns_[j];
    if (line.kind != kStatusError) next_ = j;
  } else if (seen_) {
    uint64_t n = last_n_ - last_n_ % kBlockRange + line.block;
    if (n < last_n_) n += kBlockRange;
    s.block = static_cast<uint32_t>(n);
  } else {
    s.block = line.block;
  }
  seen_ = true;
  last_n_ = s.block;
  if (line.kind == kStatusError) {
    // The last frame sent with these low bits (the board is never a field's range behind).
    const uint64_t back = (frames_sent - line.offset) & (kFieldRange - 1);
    s.offset = back <= frames_sent ? frames_sent - back : line.offset;
  } else {
    x_ = unwrap(x_, line.x, kFieldRange);
    y_ = unwrap(y_, line.y, kFieldRange);
    s.x = x_;
    s.y = y_;
  }
  return s;
}

std::string board_error_message(uint8_t code) {
  switch (code) {
#define BOARD_ERROR(name, code, message) \
  case code:                             \
    return message;
#include "board_link.def"
  }
  return tape_error_message(static_cast<TapeError>(code));
}

std::string describe(const BoardStatus& s, unsigned frac_digits) {
  const std::string n = "N" + std::to_string(s.block);
  if (s.kind == kStatusError)
    return "error in block " + n + " at offset " + std::to_string(s.offset) + ": " +
           board_error_message(s.code) + " (code " + std::to_string(s.code) + ")";
  const std::string pos = "X" + mm(s.x, frac_digits) + " Y" + mm(s.y, frac_digits) + " mm";
  return s.kind == kStatusDone ? "program done after block " + n + " at " + pos
                               : "block " + n + " playing, at " + pos;
}

}  // namespace ncinterp::board
