// Measurements of one circle method (K1..K7) on one circle: a quarter turn, many turns, and
// a single period from an exact history.
// Idea: every run starts at (R, 0) relative to the centre and goes clockwise (h > 0), the
// paper's sense. A quarter ends at the first reference point with X <= 0 (a quarter turn
// swept); a turn ends where the path crosses the positive X axis again. The radial error of
// a reference point P is |P| - R. The machine follows the chords between reference points,
// so the path error also takes the chords' sag into account (a chord dips inside the
// circle by R (1 - cos(theta/2)) ~ R h^2 / 8 even between exact points).
#pragma once
#include <cstdint>
#include <vector>

#include "arithmetic.h"
#include "method.h"
#include "op_count.h"
#include "real_point.h"

namespace ncinterp::sampled {

struct QuarterRun {
  std::vector<RealPoint> points;   // the reference points, start included
  double max_radial_error = 0;     // max | |P| - R | over the points
  double worst_angle_deg = 0;      // angle swept from the start to that point
  double end_error = 0;            // |P| - R at the last point (signed)
  double max_path_error = 0;       // max distance of the polyline (points and chords) from the circle
  OpCount ops_per_period;          // counted on the last period
  double quantum = 0;              // fixed point: the coordinate quantum; else 0
};

// Throws std::overflow_error when a fixed-point coordinate leaves the word.
QuarterRun run_quarter(Method method, double radius, double h, Starter starter, Arithmetic arith);

struct TurnsRun {
  std::vector<double> max_error_per_turn;  // max | |P| - R | in each turn
  uint64_t periods = 0;
  // How much the worst error grows per turn: (last turn - first turn) / (turns - 1).
  double drift_per_turn() const;
};

TurnsRun run_turns(Method method, double radius, double h, int turns, Starter starter, Arithmetic arith);

// The angle one period is meant to turn: h, except K6, whose period spans the indices
// i-1 .. i+1 with Y+ = Y- - 2h X (2h).
double period_angle(Method method, double h);

// One period started from exact points of the unit circle (the current point and, for K2
// and K3, the one a period before): the largest distance of the new point from the exact
// one, over 16 phases around the circle (double precision). The paper's "error on each
// step".
double local_step_error(Method method, double h);

}  // namespace ncinterp::sampled
