// Arc cases for circle-mode studies, shared by the circle tests and bench/circle: quadrant arcs
// given by their start and end relative to the centre, random arc generators, and a run of
// the golden circle DDA that measures the pulse path.
// Idea: every check is derived from the arc's geometry (programmed end, |dx|, |dy|, the
// circle through the start), never from the DDA under test.
#pragma once
#include <cstdint>
#include <random>
#include <string>

#include "arc_geometry.h"
#include "dda_circle.h"

namespace ncinterp::circle_study {

// A quadrant arc by its start (x0, y0) and end (x1, y1) relative to the centre, in BLU.
struct QuadrantArc {
  int64_t x0 = 0, y0 = 0, x1 = 0, y1 = 0;
  bool ccw = true;

  // The block's words: I, J = centre - start = (-x0, -y0); X, Y = end - start.
  ArcWords words() const {
    return ArcWords::from_signed(x1 - x0, y1 - y0, -x0, -y0, ccw);
  }
  double start_radius() const;
  double end_radius() const;
  std::string describe() const;  // "G03 from (x0, y0) to (x1, y1) about the centre"
};

// The full quadrant q (0..3, counter-clockwise from +X) of radius r, in either direction.
QuadrantArc full_quadrant(int64_t r, int q, bool ccw);

// A random good arc (check_arc() == kNone) with radius log-uniform in [1, max_radius]:
// quadrant, direction and whether it is a full quadrant are random too; partial arcs end
// at grid points rounded from the true circle, so their end radius differs by < 0.71 BLU.
QuadrantArc random_arc(std::mt19937_64& rng, int64_t max_radius);

// What the golden circle DDA does with one arc, run alone (one iteration per call).
struct ArcRunStats {
  bool finished = false;      // both counters reached 0 within the iteration limit
  uint64_t iterations = 0;    // N
  unsigned k = 0;
  int64_t x = 0, y = 0;       // final position relative to the centre
  uint64_t pulses[2][2] = {{0, 0}, {0, 0}};  // [axis][plus]
  // Largest |sqrt(x^2 + y^2) - R0| over every position after a pulse (R0 = start radius),
  // and that position.
  double max_radial_error = 0;
  int64_t worst_x = 0, worst_y = 0;
  // The same against r(phi) going linearly from R0 to the end radius R1 over the sweep
  // (the trajectory checker's arc measure, docs/verification.md).
  double max_spiral_error = 0;
};
ArcRunStats run_arc(const QuadrantArc& arc, unsigned inc_width, uint64_t max_iterations);

}  // namespace ncinterp::circle_study
