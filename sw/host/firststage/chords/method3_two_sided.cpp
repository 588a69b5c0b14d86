// Method 3, two-sided chords (Tamm, eqs. 11-23), for any curve of the Span interface.
// The chord's line is method 2's (tangent point t0 at delta on the inner side). Tamm then
// finds the point (x2', y2') of that line whose normal to the curve is delta long by a
// 2-D Newton on F(x2, x2') = G(x2, x2') = 0. The normal at C(t) meets the line at
// X(t) = C(t) + beta(t) n(t) with beta(t) = -g(t) / (nu.n(t)), g(t) = nu.(C(t) - P), so
// the same point is the root of ONE equation in the curve parameter:
//   h(t) = sigma g(t) - delta_out (nu.n(t)) = 0  (beta = -sigma delta_out),
// solved by bracketed Newton (h' = sigma nu.C' + delta_out kappa|C'| nu.T). It is the same
// point as Tamm's; the next chord starts there, off the curve, exactly as in the paper.
#include <algorithm>
#include <cmath>

#include "chords/bracketed_newton.h"
#include "chords/chord_methods.h"

namespace ncinterp::firststage {

ChordSolution two_sided_chord(const Span& span, const ChordRequest& req) {
  ChordLine line;
  ChordSolution one = one_sided_chord(span, req, &line);
  if (!one.ok || one.reaches_end || line.sigma == 0) return one;
  const int sigma = line.sigma;
  const double t0 = line.t0;
  const Vec2 nu = line.nu;
  const double dout = req.delta;
  auto h = [&](double t, double* dh) {
    const CurvePoint c = span.eval(t);
    const double sp = norm(c.d1);
    const Vec2 tan = (1.0 / sp) * c.d1;
    *dh = sigma * dot(nu, c.d1) + dout * turn_rate(c) * dot(nu, tan);
    return sigma * dot(nu, c.p - req.p) - dout * dot(nu, perp(tan));
  };
  const double t1 = one.t_cross;
  // Parabola guess: sigma g ~ -delta + a (t - t0)^2 with a from the crossing at t1.
  double step = std::max((t1 - t0) * (std::sqrt(2.0) - 1.0), 1e-9);
  double lo = t1, t = std::min({t1 + step, req.t_hi, span.next_joint(lo)}), dh;
  while (h(t, &dh) < 0) {
    if (t >= req.t_hi) {
      ChordSolution sol = one;
      sol.reaches_end = true;  // the far end lies past t_hi; t_cross is still valid
      sol.t_end = req.t_hi;
      sol.end = span.point(req.t_hi);
      return sol;
    }
    // Past an inflection the curve turns away from the line: no far end on the other side
    // here; the chord ends at its crossing, as a one-sided chord.
    if (bends_against(span, t, sigma)) return one;
    lo = t;
    step *= 2.0;
    t = std::min({t1 + step, req.t_hi, span.next_joint(lo)});
  }
  t = bracketed_newton(h, lo, t, std::min(t1 + (t1 - t0) * (std::sqrt(2.0) - 1.0), t));
  ChordSolution sol;
  sol.ok = true;
  sol.t_cross = t1;
  sol.t_end = t;
  const CurvePoint c = span.eval(t);
  sol.end = c.p - sigma * dout * perp(unit(c.d1));
  return sol;
}

}  // namespace ncinterp::firststage
