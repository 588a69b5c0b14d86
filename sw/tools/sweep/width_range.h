// The sweep's register widths: "--widths LO:HI" (or one width "W").
// Idea: parse strictly and say what is wrong in one line; the limits are those of every
// stage a width goes through (the golden model and the RTL take W = 2..32).
#pragma once
#include <string>

namespace ncinterp::sweep {

constexpr unsigned kMinWidth = 2;
constexpr unsigned kMaxWidth = 32;

struct WidthRange {
  unsigned low = 0, high = 0;  // inclusive
  unsigned count() const { return high - low + 1; }
};

// Throws std::invalid_argument ("--widths: ...") for anything but LO:HI or W with
// kMinWidth <= LO <= HI <= kMaxWidth.
WidthRange parse_width_range(const std::string& text);

}  // namespace ncinterp::sweep
