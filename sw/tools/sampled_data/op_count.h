// Operations a scheme performs, counted by the arithmetic as the scheme runs, so that
// "operations per step" in the reports is measured on the code rather than read off the
// formulas by hand.
#pragma once
#include <cstdint>

namespace ncinterp::sampled {

struct OpCount {
  uint64_t mul = 0;    // coefficient times coordinate (h Y, 0.5 h^2 X, ...)
  uint64_t add = 0;    // additions and subtractions of coordinates
  uint64_t shift = 0;  // halving (K2's 0.5 dX)

  OpCount operator-(const OpCount& o) const { return {mul - o.mul, add - o.add, shift - o.shift}; }
};

}  // namespace ncinterp::sampled
