// Method 2, one-sided chords (Tamm, eqs. 5-10), for any curve of the Span interface.
// Tamm eliminates k and y0 from eq. 8 and gets a sextic in x0 for the cubic parabola,
// solved by Newton. Here the same equation is kept in parametric form,
//   w(t0) = sigma * n(t0).(P - C(t0)) = delta,
// which is the sextic's equation for y = f(x) and works for arcs and parametric splines
// too. Its derivative is w'(t) = sigma * kappa |C'| T.(C - P) (Frenet), so Newton is
// cheap; it is safeguarded by a bracket found by doubling a first step from the local
// curvature. Then the chord line through P with the tangent direction at t0 is cut with
// the curve (eq. 10) by a bracketed Newton on g(t) = nu.(C(t) - P) = 0.
#include <algorithm>
#include <cmath>

#include "chords/bracketed_newton.h"
#include "chords/chord_methods.h"

namespace ncinterp::firststage {
namespace {

constexpr double kCurvatureEpsilon = 1e-14;  // 1/BLU: below this the curve is straight

}  // namespace

int bend_side(const Span& span, double t, double t_hi) {
  for (int i = 0; i <= 16; ++i) {
    const double ti = t + (t_hi - t) * i / 16.0;
    const CurvePoint c = span.eval(ti);
    const double k = turn_rate(c) / norm(c.d1);
    if (std::fabs(k) > kCurvatureEpsilon) return k > 0 ? 1 : -1;
  }
  return 0;
}

bool tangent_point(const Span& span, const ChordRequest& req, int sigma, double* t0) {
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
  double lo = req.ta, t = req.ta + step;
  while (w(t, &dw) < 0) {
    if (t >= req.t_hi) {
      *t0 = req.t_hi;
      return false;
    }
    lo = t;
    step *= 2.0;
    t = std::min(req.ta + step, req.t_hi);
  }
  *t0 = bracketed_newton(w, lo, t, t);
  return true;
}

ChordSolution one_sided_chord(const Span& span, const ChordRequest& req, ChordLine* line) {
  ChordSolution sol;
  const int sigma = bend_side(span, req.ta, req.t_hi);
  double t0;
  if (sigma == 0 || !tangent_point(span, req, sigma, &t0)) {
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
  double step = std::max(guess, 1e-9), lo = t0, t = std::min(t0 + step, req.t_hi);
  while (g(t, &dg) < 0) {
    if (t >= req.t_hi) {
      sol.ok = true;
      sol.reaches_end = true;
      sol.t_cross = sol.t_end = req.t_hi;
      sol.end = span.point(req.t_hi);
      return sol;
    }
    lo = t;
    step *= 2.0;
    t = std::min(t0 + step, req.t_hi);
  }
  sol.t_end = sol.t_cross = bracketed_newton(g, lo, t, t);
  sol.end = span.point(sol.t_end);
  sol.ok = true;
  return sol;
}

}  // namespace ncinterp::firststage
