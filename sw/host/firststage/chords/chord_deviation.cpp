// Exact chord deviation and foot parameters (see chord_deviation.h).
#include "chords/chord_deviation.h"

#include <algorithm>
#include <cmath>

namespace ncinterp::firststage {
namespace {

// Chords whose direction is more than 60 degrees off the curve's are not chords of it.
constexpr double kMinNormalCosine = 0.5;
// A foot parameter is found when q is this close (BLU) to the curve's normal there.
constexpr double kFootTolerance = 1e-6;

}  // namespace

double chord_deviation(const Span& span, Vec2 p, Vec2 q, double ta, double tb) {
  const Vec2 d = q - p;
  const double len = norm(d);
  if (len == 0.0 || !(tb > ta)) return kInvalidDeviation;
  const Vec2 u = (1.0 / len) * d, nu = perp(u);
  double worst = 0.0;
  auto visit = [&](const CurvePoint& c) {
    const Vec2 n = perp(unit(c.d1));
    const double m = dot(nu, n);
    if (m < kMinNormalCosine) {
      worst = kInvalidDeviation;
      return;
    }
    worst = std::max(worst, std::fabs(dot(nu, c.p - p) / m));
  };
  const CurvePoint ca = span.eval(ta), cb = span.eval_before(tb);
  visit(ca);
  visit(cb);
  worst = std::max({worst, norm(p - ca.p), norm(q - cb.p)});
  // The 60-degree guard must hold over the whole span, not only where beta is stationary:
  // a curve may turn back between those points (a hairpin whose tangent sweeps through
  // +-90 degrees and never becomes antiparallel to the chord). Its tangent leaves the cone
  // only through one of the cone's edges, u turned by +-60 degrees: a tangent parallel to
  // an edge strictly inside the span rejects the chord. (Found by the airfoil fuzzer: a
  // needle of a scrambled airfoil left out by a method-3 chord, 0.52 mm at tol 0.1.)
  const double edge_sin = std::sqrt(1.0 - kMinNormalCosine * kMinNormalCosine);
  const Vec2 edges[2] = {kMinNormalCosine * u + edge_sin * nu, kMinNormalCosine * u - edge_sin * nu};
  const int first = span.index(ta), last = span.index(std::nextafter(tb, ta));
  for (int i = first; i <= last && worst != kInvalidDeviation; ++i) {
    const double u0 = std::max(ta - i, 0.0), u1 = std::min(tb - i, 1.0);
    double roots[4];
    for (const Vec2& edge : edges) {
      const int k = span.segment(i).tangent_parallel(edge, u0, u1, roots);
      for (int r = 0; r < k; ++r)
        if (roots[r] > u0 && roots[r] < u1) return kInvalidDeviation;
    }
    const int k = span.segment(i).tangent_parallel(u, u0, u1, roots);
    for (int r = 0; r < k; ++r) visit(span.segment(i).eval(roots[r]));
    if (i > first) {  // joint at t = i: both sides (the normal may turn a little there)
      visit(span.segment(i - 1).eval(1.0));
      visit(span.segment(i).eval(0.0));
    }
  }
  return worst;
}

double foot_parameter(const Span& span, Vec2 q, double guess, double lo, double hi) {
  // f(t) = (C(t) - q).T(t) grows through zero at the foot; f' = |C'| (1 + kappa (C-q).n).
  auto f = [&](double t, double* df) {
    const CurvePoint c = span.eval(t);
    const double sp = norm(c.d1);
    const Vec2 tan = (1.0 / sp) * c.d1;
    const Vec2 r = c.p - q;
    *df = sp * (1.0 + turn_rate(c) / sp * dot(r, perp(tan)));
    return dot(r, tan);
  };
  double t = std::clamp(guess, lo, hi), df;
  // Newton from the guess; then a bracketed search if it wanders.
  for (int it = 0; it < 12; ++it) {
    const double v = f(t, &df);
    // v is q's offset along the tangent (BLU): a micro-BLU is converged. (A test on the
    // step in t alone never passes far from the origin, where v's rounding noise moves t
    // by more than any fixed relative step.)
    if (std::fabs(v) <= kFootTolerance) return t;
    if (!(df > 0)) break;
    const double next = std::clamp(t - v / df, lo, hi);
    if (std::fabs(next - t) <= 1e-13 * (1.0 + std::fabs(t))) return next;
    t = next;
  }
  // Bracket: scan for the nearest sample, then bisect f around it.
  const int samples = 64;
  double best_t = lo, best_d = std::numeric_limits<double>::infinity();
  for (int i = 0; i <= samples; ++i) {
    const double ti = lo + (hi - lo) * i / samples;
    const double di = norm(span.point(ti) - q);
    if (di < best_d) best_d = di, best_t = ti;
  }
  double a = std::max(lo, best_t - (hi - lo) / samples), b = std::min(hi, best_t + (hi - lo) / samples);
  if (f(a, &df) >= 0) return a;
  if (f(b, &df) <= 0) return b;
  for (int it = 0; it < 60 && b - a > 1e-14 * (1.0 + std::fabs(a)); ++it) {
    const double m = 0.5 * (a + b);
    (f(m, &df) < 0 ? a : b) = m;
  }
  return 0.5 * (a + b);
}

}  // namespace ncinterp::firststage
