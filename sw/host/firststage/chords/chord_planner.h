// Chord planner: replaces one span of the contour by chords whose ends lie on the BLU
// grid, each within delta of the curve (Kolesnikov's normal measure) AFTER rounding.
// Idea: the chosen method (chord_methods.h) proposes a continuous chord end; the planner
// caps it to the increment register (the paper's dy_max), then tries the grid points
// around it and keeps the admissible one that gets farthest along the curve: rounding
// goes to the safe side, as Tamm prescribes, but decided by the exact deviation of the
// rounded chord instead of a sign rule. If no neighbour is admissible the method is asked
// again with a smaller delta; as a last resort a bisection over chord ends on the curve
// (always possible since delta >= 1 BLU). Every chord starts where the last one ended (a
// grid point), so the increments sum exactly to the span's end: no drift.
#pragma once
#include <cstdint>
#include <vector>

#include "chords/chord_methods.h"
#include "chords/span.h"
#include "geometry/grid_point.h"

namespace ncinterp::firststage {

GridPoint round_to_grid(Vec2 v);

struct PlannerOptions {
  int method = 3;           // 1 trial, 2 one-sided, 3 two-sided
  double delta = 9.0;       // allowed deviation of every rounded chord, BLU
  int64_t max_inc = 65535;  // |dx|, |dy| of one chord, BLU (2^W - 1)
};

struct ChordEnd {
  GridPoint p;      // chord end, BLU
  int segment = 0;  // span segment that holds the chord's end
};

struct PlannerStats {
  long chords = 0;
  long retries = 0;    // method asked again with a smaller delta after rounding failed
  long fallbacks = 0;  // chords found by the bisection fallback
};

class ChordPlanner {
 public:
  explicit ChordPlanner(const PlannerOptions& options) : opt_(options) {}
  // Appends the chords from `start` to `end` (grid points near the span's ends); the last
  // appended end is `end`. Throws std::runtime_error when no admissible chord exists.
  void plan(const Span& span, GridPoint start, GridPoint end, std::vector<ChordEnd>& out);
  const PlannerStats& stats() const { return stats_; }

 private:
  // The admissible grid point near `e` (foot te) reaching farthest; false if none.
  bool round_end(const Span& span, GridPoint p, double ta, Vec2 e, double te, GridPoint end,
                 GridPoint* q, double* tb) const;
  bool fallback(const Span& span, GridPoint p, double ta, GridPoint end, GridPoint* q,
                double* tb) const;
  // False when c (not `end`) lies so near `end` that the last chord could not follow: a
  // chord of a few BLU from up to delta outside onto the end crosses the curve almost
  // along its normal, which no chord may do. Such a c is kept only if c -> end is
  // admissible.
  bool leaves_room(const Span& span, GridPoint c, double tc, GridPoint end) const;
  // Method 3 near the span's end: true when a chord from this chord's crossing (on the
  // curve) reaches `end`. Ending there (fig. 9 again) costs no chord and spares the span a
  // short last chord that turns steeply back from delta outside onto the end point, which
  // the cutter offset could not follow (it would leave the end uncut).
  bool ends_at_crossing(const Span& span, const ChordSolution& sol, double ta, GridPoint end) const;
  bool admissible(const Span& span, GridPoint p, double ta, GridPoint q, double tb) const;

  PlannerOptions opt_;
  PlannerStats stats_;
};

}  // namespace ncinterp::firststage
