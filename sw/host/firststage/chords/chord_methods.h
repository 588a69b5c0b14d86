// Tamm's three ways to find the next chord from a point P near the curve (paper 000).
// Each returns the continuous (unquantised) chord end; the planner (chord_planner.h) puts
// it on the BLU grid, checks it, and applies zones, corners and the register width.
//   1 trial (Karibsky): try a chord P -> C(ta + h), shrink h while it deviates more than
//     delta, grow it while it does not; keep the last admissible. Fixed relative step.
//   2 one-sided: the longest chord at once: its direction is the tangent at the point
//     t0 where that tangent, moved through P, is exactly delta from C(t0) (eq. 8); it ends
//     where it crosses the curve again (eq. 10).
//   3 two-sided: the chord of method 2 continued past the crossing until it is delta away
//     from the curve on the other side (eqs. 11-15); the next chord starts there.
#pragma once
#include "chords/span.h"

namespace ncinterp::firststage {

struct ChordRequest {
  Vec2 p;             // start (BLU), on or near the curve
  double ta = 0.0;    // foot parameter of p
  double t_hi = 0.0;  // the chord must not pass this parameter (zone or span end)
  double delta = 0.0;  // allowed deviation (BLU)
};

struct ChordSolution {
  bool reaches_end = false;  // the method's chord reaches or passes t_hi
  bool ok = false;           // false: the method found no chord (the planner falls back)
  double t_cross = 0.0;      // method 3: where the line crosses the curve; else = t_end
  double t_end = 0.0;        // foot parameter of the chord's end
  Vec2 end;                  // continuous chord end (BLU)
};

// Method 1. `step` carries the last admissible parameter step from chord to chord (0 at
// the start of a span: a first guess from the curvature is used).
ChordSolution trial_chord(const Span& span, const ChordRequest& req, double* step);
// The line of a method-2 chord: bend side, tangent point and the line's unit normal.
struct ChordLine {
  int sigma = 0;
  double t0 = 0.0;
  Vec2 nu;
};
// Method 2 (the tangent-point equation solved by bracketed Newton on t0; see the .cpp).
// `line` (optional) receives the chord's line when the solution does not reach t_hi and
// is a one-sided chord (line->sigma stays 0 for a chord found by trial past an inflection).
ChordSolution one_sided_chord(const Span& span, const ChordRequest& req,
                              ChordLine* line = nullptr);
// Method 3 (method 2, then the far end by Newton on one variable).
ChordSolution two_sided_chord(const Span& span, const ChordRequest& req);

// Growth factor of method 1's trial step.
constexpr double kTrialStepFactor = 1.05;

// Shared by methods 2 and 3: the tangent point t0 of the chord from req.p (eq. 8 in
// parametric form: sigma * n(t0).(P - C(t0)) = delta). kNone when no such point exists
// before t_hi (then *t0 = t_hi); kInflection when the curve bends the other way before
// it is reached (*t0: where the search saw that). sigma: the side the curve bends to
// (+1 left).
enum class TangentPoint { kFound, kNone, kInflection };
TangentPoint tangent_point(const Span& span, const ChordRequest& req, int sigma, double* t0);
// The side the curve bends to after t (+1 left, -1 right, 0 straight as far as t_hi).
int bend_side(const Span& span, double t, double t_hi);
// True when the curve at t bends to the other side than sigma (past an inflection).
bool bends_against(const Span& span, double t, int sigma);

}  // namespace ncinterp::firststage
