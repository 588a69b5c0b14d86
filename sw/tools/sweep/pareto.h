// The Pareto view of a grid: the points no other point beats on every objective (area,
// total error, tape length), and the recommendation per target board picked from that
// front by a fixed rule.
// Idea: only points that passed every check on every input and whose objectives were all
// measured take part (a gap is never filled with an estimate). When no such point has an
// area (a --no-synth run), the front is over error and tape length alone and says so. The
// rule for a board: among the front's points that fit it, the smallest total error (closer
// than 0.1 um is a tie), then the shortest tape, then the smallest area, then the smallest
// feed error (what a faster clock buys), then the first in grid order; so the choice is
// reproducible and never made by hand. A point fits a board when the placement judged
// holds it and its Fmax reaches the point's clock (clock_hz: a design point at 48 MHz is
// no pick for a part that places it at 32 MHz).
#pragma once
#include <optional>
#include <string>
#include <vector>

#include "point_run.h"

namespace ncinterp::sweep {

struct ParetoFront {
  std::vector<std::string> objectives;  // "ice40_logic_cells", "total_error_max_mm", "tape_frames"
  std::vector<size_t> members;          // indices into the results, in grid order
  size_t eligible = 0;                  // points that passed and had every objective measured
};

ParetoFront pareto_front(const std::vector<PointResult>& results);

struct Board {
  std::string name;
  double logic_cells = 0;       // capacity
  bool small_part = false;      // fit judged by the HX1K placement (else by the HX8K's count)
};
// HX1K (1280, placed on the HX1K TQ144), UP5K (5280, judged by the HX8K placement: its
// count, and its Fmax, which is optimistic for the UP5K's slower fabric), HX8K (7680,
// placed on the HX8K CT256).
const std::vector<Board>& target_boards();

struct Recommendation {
  Board board;
  std::optional<size_t> point;  // index into the results
  std::string why;              // the rule's outcome, or why there is no point
};

// default_clock_hz: the clock of a point that does not set clock_hz.
std::vector<Recommendation> recommend(const std::vector<PointResult>& results, const ParetoFront& front,
                                      double default_clock_hz);

}  // namespace ncinterp::sweep
