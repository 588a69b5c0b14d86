// Method 1, trial chords (Tamm after Karibsky): pick a step, compute the chord to the curve
// point that far along and its maximum deviation d; while d > delta shrink the step, while
// d < delta grow it, and print the last admissible chord. The step is in the curve
// parameter (dx for y = f(x)) and changes by a fixed factor, as a machine of 1960 would
// do it; the deviation is the exact one of chord_deviation.h. The result is a one-sided
// chord up to kTrialStepFactor shorter than method 2's, found with many more evaluations.
#include <algorithm>
#include <cmath>

#include "chords/chord_deviation.h"
#include "chords/chord_methods.h"

namespace ncinterp::firststage {

ChordSolution trial_chord(const Span& span, const ChordRequest& req, double* step) {
  auto deviation = [&](double h) {
    const double te = std::min(req.ta + h, req.t_hi);
    return chord_deviation(span, req.p, span.point(te), req.ta, te);
  };
  const double room = req.t_hi - req.ta;
  double h = *step;
  if (!(h > 0)) {  // first chord of a span: a guess from the local curvature
    const CurvePoint c = span.eval(req.ta);
    const double kappa = std::fabs(turn_rate(c)) / norm(c.d1);
    h = kappa > 0 ? std::sqrt(8.0 * req.delta / kappa) / norm(c.d1) : room;
  }
  h = std::min(h, room);
  ChordSolution sol;
  if (deviation(h) > req.delta) {
    for (int it = 0; it < 2000 && deviation(h) > req.delta; ++it) h /= kTrialStepFactor;
    if (deviation(h) > req.delta) return sol;  // not ok: the planner falls back
  } else {
    while (h < room) {
      const double longer = std::min(h * kTrialStepFactor, room);
      if (deviation(longer) > req.delta) break;
      h = longer;
    }
  }
  *step = h;
  sol.ok = true;
  sol.t_end = sol.t_cross = std::min(req.ta + h, req.t_hi);
  sol.reaches_end = sol.t_end >= req.t_hi;
  sol.end = span.point(sol.t_end);
  return sol;
}

}  // namespace ncinterp::firststage
