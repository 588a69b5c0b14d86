// A good arc block for tape tests: a full quadrant from axis to axis about its centre.
#pragma once
#include <cstdint>

#include "tape.h"

namespace ncinterp::tape {

// Quadrant q (0..3, counter-clockwise from +X) of the circle of radius r about the
// centre, in the arc's direction: the block's increments, its centre relative to the
// start (I, J) and feed.
inline Block quadrant_arc(uint32_t n, int64_t r, int q, bool ccw, uint64_t feed) {
  const int64_t ax[4] = {r, 0, -r, 0}, ay[4] = {0, r, 0, -r};
  const int from = ccw ? q : (q + 1) % 4, to = ccw ? (q + 1) % 4 : q;
  return {n, ccw ? Motion::kArcCcw : Motion::kArcCw, ax[to] - ax[from], ay[to] - ay[from],
          -ax[from], -ay[from], feed};
}

}  // namespace ncinterp::tape
