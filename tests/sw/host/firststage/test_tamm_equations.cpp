// Methods 2 and 3 give Tamm's chords (paper 000). The library solves the tangent-point
// equation in parametric form with a bracketed Newton (method2_one_sided.cpp); here Tamm's
// own equations for y = f(x) are solved by plain bisection, independently:
//   eq. 8:  delta * sqrt(1 + k^2) = y0 - k (x0 - a) - b,  k = f'(x0)  (the tangent point),
//   eq. 10: f(x) - b - k (x - a) = 0 beyond x0                       (the chord's end);
// and method 3's far end is checked to be the point of that line whose normal to the curve
// is delta long (eqs. 11-15): its nearest curve point, found by dense sampling, is delta away
// and its normal passes through it.
#include <gtest/gtest.h>

#include <cmath>
#include <functional>

#include "chords/chord_methods.h"
#include "chords/span.h"

namespace ncinterp::firststage {
namespace {

// The first root of g in (lo, hi] by scanning and bisection.
double first_root(const std::function<double(double)>& g, double lo, double hi) {
  const int n = 20000;
  double a = lo, ga = g(lo + 1e-12 * (hi - lo));
  for (int i = 1; i <= n; ++i) {
    double b = lo + (hi - lo) * i / n;
    const double gb = g(b);
    if ((ga < 0) != (gb < 0)) {
      for (int it = 0; it < 200; ++it) {
        const double m = 0.5 * (a + b);
        ((g(m) < 0) == (ga < 0) ? a : b) = m;
      }
      return 0.5 * (a + b);
    }
    a = b;
    ga = gb;
  }
  return NAN;
}

struct Cubic {
  double A, B, C, D;
  double f(double x) const { return ((A * x + B) * x + C) * x + D; }
  double df(double x) const { return (3 * A * x + 2 * B) * x + C; }
};

TEST(TammEquations, MethodTwoSolvesEquationsEightAndTen) {
  const Cubic cubics[] = {{0.0005, -0.01, 0.3, 2.0}, {-0.002, 0.05, -0.4, 1.0}, {0.0, 0.02, 0.1, 0.0}};
  int checked = 0;
  for (const Cubic& q : cubics) {
    const double x_from = 0.0, x_to = 12.0;
    const Segment seg = Segment::cubic_parabola(q.A, q.B, q.C, q.D, x_from, x_to);
    const Span span(&seg, 1);
    for (double a : {0.5, 3.0, 7.0}) {
      const double b = q.f(a), delta = 0.01;
      const ChordRequest req{{a, b}, (a - x_from) / (x_to - x_from), 1.0, delta};
      ChordLine line;
      const ChordSolution sol = one_sided_chord(span, req, &line);
      // Not Tamm's case: no tangent point before the end of the cubic, or an inflection
      // first (the library then finds the chord by trial; line.sigma stays 0).
      if (sol.reaches_end || line.sigma == 0) continue;
      ++checked;
      // Eq. 8 with its sign for the side the curve bends to (sigma = +1: f'' > 0, the
      // tangents pass below P): -sigma (y0 - k (x0 - a) - b) = delta sqrt(1 + k^2).
      const double sigma = line.sigma;
      const double x0 = first_root([&](double x) {
        const double k = q.df(x);
        return -sigma * (q.f(x) - k * (x - a) - b) - delta * std::sqrt(1 + k * k);
      }, a, x_to);
      ASSERT_TRUE(std::isfinite(x0)) << "a=" << a;
      EXPECT_NEAR(x_from + line.t0 * (x_to - x_from), x0, 1e-7) << "tangent point, a=" << a;
      const double k = q.df(x0);
      const double x1 = first_root([&](double x) { return q.f(x) - b - k * (x - a); }, x0, x_to);
      ASSERT_TRUE(std::isfinite(x1));
      EXPECT_NEAR(sol.end.x, x1, 1e-7) << "chord end, a=" << a;
      EXPECT_NEAR(sol.end.y, q.f(x1), 1e-7);
    }
  }
  EXPECT_GE(checked, 7);
}

TEST(TammEquations, MethodThreeFarEndIsDeltaAlongTheNormal) {
  const Cubic q{0.0005, -0.01, 0.3, 2.0};
  const Segment seg = Segment::cubic_parabola(q.A, q.B, q.C, q.D, 0.0, 12.0);
  const Span span(&seg, 1);
  const double a = 1.0, delta = 0.01;
  const ChordRequest req{{a, q.f(a)}, a / 12.0, 1.0, delta};
  ChordLine line;
  const ChordSolution one = one_sided_chord(span, req, &line);
  const ChordSolution two = two_sided_chord(span, req);
  ASSERT_FALSE(two.reaches_end);
  // On the same line as method 2's chord, past its crossing.
  const Vec2 d = two.end - req.p;
  EXPECT_NEAR(dot(d, line.nu), 0.0, 1e-9);
  EXPECT_GT(two.end.x, one.end.x);
  // Nearest curve point by dense sampling and golden-section refinement.
  const auto dist = [&](double x) { return std::hypot(x - two.end.x, q.f(x) - two.end.y); };
  double best_x = 0, best = 1e300;
  for (int i = 0; i <= 120000; ++i) {
    const double x = 12.0 * i / 120000;
    if (dist(x) < best) best = dist(x), best_x = x;
  }
  double lo = best_x - 1e-4, hi = best_x + 1e-4;
  for (int it = 0; it < 200; ++it) {
    const double m1 = lo + (hi - lo) / 3, m2 = hi - (hi - lo) / 3;
    (dist(m1) < dist(m2) ? hi : lo) = (dist(m1) < dist(m2) ? m2 : m1);
  }
  const double xf = 0.5 * (lo + hi);
  EXPECT_NEAR(dist(xf), delta, 1e-9);
  // The curve's normal at the foot passes through the far end: the tangent is
  // perpendicular to (end - foot).
  EXPECT_NEAR((two.end.x - xf) * 1.0 + (two.end.y - q.f(xf)) * q.df(xf), 0.0, 1e-9);
}

}  // namespace
}  // namespace ncinterp::firststage
