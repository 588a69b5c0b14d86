// The interpolator's path bounds, BLU: how far a pulse position may lie from the block's
// programmed path (docs/interpolator.md 5.6, docs/circle-dda.md 3.2). The one definition the
// play monitor (play's path_within_bound) and the trajectory checker (its bound rule) use.
// Idea: both judge the same pulses against the same promise, so they must not disagree on it.
#pragma once
#include <cmath>
#include <cstdint>

#include "dda_circle.h"

namespace ncinterp {

// A line block of the L1 DDA: (|dx| + |dy|) / (2 sqrt(dx^2 + dy^2)), 0 for a zero move.
inline double line_path_bound(int64_t dx, int64_t dy) {
  if (dx == 0 && dy == 0) return 0.0;
  const double ax = std::fabs(static_cast<double>(dx)), ay = std::fabs(static_cast<double>(dy));
  return (ax + ay) / (2.0 * std::hypot(ax, ay));
}

// An arc block, from the circle through its start (radius r0; r1 the end's radius about the
// same centre): dda_bound + |r1 - r0| (dda_circle.h).
inline double arc_path_bound(double r0, double r1, double dda_bound = kCircleDdaBound) {
  return dda_bound + std::fabs(r1 - r0);
}

}  // namespace ncinterp
