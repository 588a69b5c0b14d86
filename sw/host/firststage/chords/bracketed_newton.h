// Newton's method kept inside a bracket (bisection when a step would leave it): the root
// finder every chord method uses. f(t, &df) returns f(t) and f'(t); f(lo) < 0 <= f(hi).
#pragma once
#include <algorithm>
#include <cmath>

namespace ncinterp::firststage {

template <class F>
double bracketed_newton(F f, double lo, double hi, double guess) {
  double t = std::clamp(guess, lo, hi);
  for (int it = 0; it < 60; ++it) {
    double df;
    const double v = f(t, &df);
    if (v < 0) lo = t; else hi = t;
    if (v == 0.0 || hi - lo <= 1e-13 * (1.0 + std::fabs(hi))) break;
    double next = df != 0.0 ? t - v / df : 0.5 * (lo + hi);
    if (!(next > lo && next < hi)) next = 0.5 * (lo + hi);
    if (std::fabs(next - t) <= 1e-14 * (1.0 + std::fabs(t))) {
      t = next;
      break;
    }
    t = next;
  }
  return t;
}

}  // namespace ncinterp::firststage
