// Measurement of L1 on one line block.
// Idea: the block goes from the origin to E = L (cos a, sin a); V T = h L, the same path
// per period as a circle of radius L at step h, so L1 and K1..K7 share the h axis. The
// paper's L1 has no rule for the remainder L - N V T: the run makes N = round(1 / h)
// periods, as written, and reports how far the last point is from E (the price of that
// omission and of rounding h_k), and how far any point is from the line (rounding of h_k).
#pragma once
#include <cstdint>
#include <vector>

#include "arithmetic.h"
#include "op_count.h"
#include "real_point.h"

namespace ncinterp::sampled {

struct LineRun {
  std::vector<RealPoint> points;  // start included
  double max_deviation = 0;       // largest distance of a point from the line through 0 and E
  double endpoint_error = 0;      // |last point - E|
  OpCount ops_per_period;
  double quantum = 0;             // fixed point: the coordinate quantum; else 0
};

LineRun run_line(double length, double angle_rad, double h, Arithmetic arith);

}  // namespace ncinterp::sampled
