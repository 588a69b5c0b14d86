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
namespace {

// Shortenings by kTrialStepFactor before the trial looks along the whole room instead
// (130 times shorter).
constexpr int kTrialShrinks = 100;

}  // namespace

ChordSolution trial_chord(const Span& span, const ChordRequest& req, double* step) {
  auto deviation = [&](double h) {
    const double te = std::min(req.ta + h, req.t_hi);
    return chord_deviation(span, req.p, span.point(te), req.ta, te);
  };
  // A chord that starts off the curve (method 3's far end, when methods 2 and 3 hand an
  // inflection over to the trial) deviates by its start's offset at least; the rest of the
  // chord is held to delta.
  const double allowed = std::max(req.delta, norm(req.p - span.point(req.ta)));
  const double room = req.t_hi - req.ta;
  double h = *step;
  if (!(h > 0)) {  // first chord of a span: a guess from the local curvature
    const CurvePoint c = span.eval(req.ta);
    const double kappa = std::fabs(turn_rate(c)) / norm(c.d1);
    h = kappa > 0 ? std::sqrt(8.0 * req.delta / kappa) / norm(c.d1) : room;
  }
  h = std::min(h, room);
  ChordSolution sol;
  const auto fits = [&](double x) { return deviation(x) <= allowed; };
  bool ok = fits(h);
  if (!ok) {
    for (int it = 0; it < kTrialShrinks && !ok; ++it) {
      h /= kTrialStepFactor;
      ok = fits(h);
    }
    if (!ok) {
      // From a start off the curve a short chord is steep (it crosses the curve almost
      // along the normal) and only a longer one fits: look along the whole room in coarse
      // steps for the longest chord that fits, then refine it as above.
      double found = 0.0;
      for (double x = room; x > room * 1e-6; x /= 1.5)
        if (fits(x)) {
          found = x;
          break;
        }
      if (found == 0.0) return sol;  // not ok: the planner falls back
      h = found;
    }
  }
  while (h < room) {
    const double longer = std::min(h * kTrialStepFactor, room);
    if (!fits(longer)) break;
    h = longer;
  }
  *step = h;
  sol.ok = true;
  sol.t_end = sol.t_cross = std::min(req.ta + h, req.t_hi);
  sol.reaches_end = sol.t_end >= req.t_hi;
  sol.end = span.point(sol.t_end);
  return sol;
}

}  // namespace ncinterp::firststage
