// Method 2, one-sided chords (Tamm, eqs. 5-10), for any curve of the Span interface.
// Tamm eliminates k and y0 from eq. 8 and gets a sextic in x0 for the cubic parabola,
// solved by Newton. Here the same equation is kept in parametric form,
//   w(t0) = sigma * n(t0).(P - C(t0)) = delta,
// which is the sextic's equation for y = f(x) and works for arcs and parametric splines
// too. Its derivative is w'(t) = sigma * kappa |C'| T.(C - P) (Frenet), so Newton is
// cheap; it is safeguarded by a bracket found by doubling a first step from the local
// curvature. Then the chord line through P with the tangent direction at t0 is cut with
// the curve (eq. 10) by a bracketed Newton on g(t) = nu.(C(t) - P) = 0.
// Tamm's curves bend one way between reference points; a span may hold an inflection
// (a cubic's, or an S-bend of arcs). When the curve turns the other way before the tangent
// point is reached, no one-sided chord exists from P and the chord is found by trial.
#include <algorithm>
#include <cmath>

#include "chords/bracketed_newton.h"
#include "chords/chord_methods.h"

namespace ncinterp::firststage {
namespace {

constexpr double kCurvatureEpsilon = 1e-14;  // 1/BLU: below this the curve is straight

}  // namespace

bool bends_against(const Span& span, double t, int sigma) {
  const CurvePoint c = span.eval(t);
  return sigma * turn_rate(c) / norm(c.d1) < -kCurvatureEpsilon;
}

int bend_side(const Span& span, double t, double t_hi) {
  // The nearest bend after t: a few probes closing in on t within each segment (a cubic
  // may start at its inflection), segment after segment.
  for (double a = t; a < t_hi; a = span.next_joint(a)) {
    const double b = std::min(span.next_joint(a), t_hi);
    for (const double f : {0.0, 1.0 / 256, 1.0 / 32, 0.25, 0.75}) {
      const CurvePoint c = span.eval(a + f * (b - a));
      const double k = turn_rate(c) / norm(c.d1);
      if (std::fabs(k) > kCurvatureEpsilon) return k > 0 ? 1 : -1;
    }
  }
  return 0;
}

TangentPoint tangent_point(const Span& span, const ChordRequest& req, int sigma, double* t0) {
  auto w = [&](double t, double* dw) {
    const CurvePoint c = span.eval(t);
    const double sp = norm(c.d1);
    const Vec2 tan = (1.0 / sp) * c.d1;
    const Vec2 r = req.p - c.p;
    *dw = sigma * turn_rate(c) * dot(tan, c.p - req.p);
    return sigma * dot(perp(tan), r) - req.delta;
  };
  // First step: the arc length at which a parabola of the local curvature reaches delta.
  const CurvePoint ca = span.eval(req.ta);
  double dw;
  const double w0 = w(req.ta, &dw);
  const double kappa = std::fabs(turn_rate(ca)) / norm(ca.d1);
  double step = kappa > kCurvatureEpsilon
                    ? std::sqrt(2.0 * std::max(-w0, 0.0) / kappa) / norm(ca.d1)
                    : req.t_hi - req.ta;
  step = std::clamp(step, 1e-9, req.t_hi - req.ta);
  double lo = req.ta, t = std::min(req.ta + step, span.next_joint(lo));
  while (w(t, &dw) < 0) {
    if (t >= req.t_hi) {
      *t0 = req.t_hi;
      return TangentPoint::kNone;
    }
    if (bends_against(span, t, sigma)) {
      *t0 = t;
      return TangentPoint::kInflection;
    }
    lo = t;
    step *= 2.0;
    t = std::min(req.ta + step, span.next_joint(lo));
  }
  *t0 = bracketed_newton(w, lo, t, t);
  return TangentPoint::kFound;
}

ChordSolution one_sided_chord(const Span& span, const ChordRequest& req, ChordLine* line) {
  ChordSolution sol;
  const int sigma = bend_side(span, req.ta, req.t_hi);
  double t0 = req.t_hi;
  const TangentPoint found = sigma == 0 ? TangentPoint::kNone : tangent_point(span, req, sigma, &t0);
  // Past an inflection no one-sided chord exists (the curve turns the other way before
  // the tangent point, or before it meets the tangent's line again): the longest
  // admissible chord is then found by trial (method 1), from its first guess (the curve
  // is nearly straight there, so the guess is long and the trial shortens it).
  const auto by_trial = [&]() {
    double step = 0.0;
    return trial_chord(span, req, &step);
  };
  if (found == TangentPoint::kInflection) return by_trial();
  if (found == TangentPoint::kNone) {
    sol.ok = true;
    sol.reaches_end = true;
    sol.t_cross = sol.t_end = req.t_hi;
    sol.end = span.point(req.t_hi);
    return sol;
  }
  const Vec2 nu = perp(unit(span.eval(t0).d1));
  if (line) *line = {sigma, t0, nu};
  // sigma * g rises from -delta at t0 to 0 at the crossing.
  auto g = [&](double t, double* dg) {
    const CurvePoint c = span.eval(t);
    *dg = sigma * dot(nu, c.d1);
    return sigma * dot(nu, c.p - req.p);
  };
  double dg;
  // First guess from the parabola through g(ta) with its vertex -delta at t0.
  const double ga = g(req.ta, &dg);
  const double guess =
      (t0 - req.ta) * std::sqrt(req.delta / std::max(req.delta + ga, 1e-12 * req.delta));
  double step = std::max(guess, 1e-9), lo = t0, t = std::min({t0 + step, req.t_hi, span.next_joint(lo)});
  while (g(t, &dg) < 0) {
    if (t >= req.t_hi) {
      sol.ok = true;
      sol.reaches_end = true;
      sol.t_cross = sol.t_end = req.t_hi;
      sol.end = span.point(req.t_hi);
      return sol;
    }
    if (bends_against(span, t, sigma)) return by_trial();
    lo = t;
    step *= 2.0;
    t = std::min({t0 + step, req.t_hi, span.next_joint(lo)});
  }
  sol.t_end = sol.t_cross = bracketed_newton(g, lo, t, t);
  sol.end = span.point(sol.t_end);
  sol.ok = true;
  return sol;
}

}  // namespace ncinterp::firststage
