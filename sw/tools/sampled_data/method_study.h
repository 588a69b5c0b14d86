// The study behind `ncinterp methods`: every method over a grid of h and radii, measured
// in double and in fixed point, with the error laws fitted per method.
// Idea: one row per (method, radius, h) holds everything measured there (quarter circle,
// many turns, one period, fixed point); a summary per method fits e = c h^p R to the rows.
// A double result is trusted only where round-off does not decide it: each row is run in
// long double too, and a quantity that changes by more than 1% is "round-off limited" and
// left out of the fits (the high-order methods reach that floor at small h).
#pragma once
#include <cstdint>
#include <limits>
#include <vector>

#include "method.h"
#include "op_count.h"
#include <functional>

#include "order_fit.h"

namespace ncinterp::sampled {

struct StudyConfig {
  std::vector<double> radii_mm;
  std::vector<double> hs;
  int turns = 10;       // for the drift: at least 2
  int word_bits = 32;   // fixed-point word length B
  Starter starter = Starter::kK7;
  // Called after each measured row with (rows done, rows in all): a progress display.
  std::function<void(size_t, size_t)> progress;
};

// h from 1e-4 to 1e-1, four points per decade; radii 1, 10 and 100 mm.
std::vector<double> default_h_sweep();
std::vector<double> default_radii_mm();

// L1's line in the study: length R, at this angle to the X axis (both axes move).
constexpr double kLineAngleDeg = 30.0;

struct StudyRow {
  static constexpr double kNone = std::numeric_limits<double>::quiet_NaN();

  Method method = Method::kK1;
  double radius = 0, h = 0;
  uint64_t periods = 0;            // in the quarter (L1: in the line)
  double error = 0;                // K: max radial error of the quarter's points; L1: max distance from the line
  double path_error = 0;           // also along the chords between points
  double end_error = 0;            // K: |P| - R at the quarter's last point; L1: distance of the last point from the end
  double worst_angle_deg = kNone;  // K: angle swept where `error` occurs
  double first_turn_error = kNone, last_turn_error = kNone, drift_per_turn = kNone;  // K
  double local_error = kNone;      // K: one period from exact points, relative to R
  double fixed_error = 0;          // `error` in fixed point (config.word_bits)
  double fixed_minus_double = 0;   // largest distance between a fixed-point point and its double twin
  double quantum = 0;              // the fixed-point coordinate quantum, mm
  double paper_error = kNone;      // the paper's quarter formula here (quarter_claim)
  bool roundoff_limited = false;   // `error` moves by more than 1% in long double
  bool drifts = false;             // last turn's error > 1.1 x first turn's, and not round-off
  OpCount ops_per_period;
};

struct MethodSummary {
  Method method = Method::kK1;
  OrderFit error;  // error / R against h, rows not round-off limited
  OrderFit local;  // local_error against h
  OrderFit drift;  // drift_per_turn / R against h, rows that drift
  int rows = 0, roundoff_rows = 0, drifting_rows = 0;
  OpCount ops_per_period;
};

struct Study {
  StudyConfig config;
  std::vector<StudyRow> rows;  // method-major, then radius, then h
  std::vector<MethodSummary> summaries;
};

// Throws std::invalid_argument on a bad configuration and std::overflow_error when the
// fixed-point word cannot hold a run.
Study run_study(const StudyConfig& config);

}  // namespace ncinterp::sampled
