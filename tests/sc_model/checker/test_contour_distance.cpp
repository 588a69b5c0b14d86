// ContourDistance against independent references: the closed-form distance to circles and
// lines, and a brute-force search (dense sampling, then golden-section refinement around
// every local minimum of the samples) on random cubic pieces.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>

#include "contour_distance.h"

namespace ncinterp::checker {
namespace {

using firststage::Segment;

// Brute force: 20000 samples, then a golden-section search in the bracket of every sample
// that is a local minimum. Independent of the branch-and-bound code.
double brute_distance(const Segment& s, Vec2 q) {
  const int n = 20000;
  std::vector<double> d(n + 1);
  for (int i = 0; i <= n; ++i) d[i] = norm(s.point(static_cast<double>(i) / n) - q);
  double best = std::min(d[0], d[n]);
  for (int i = 1; i < n; ++i) {
    if (d[i] > d[i - 1] || d[i] > d[i + 1]) continue;
    double a = static_cast<double>(i - 1) / n, b = static_cast<double>(i + 1) / n;
    const double g = 0.5 * (std::sqrt(5.0) - 1.0);
    for (int it = 0; it < 100; ++it) {
      const double c = b - g * (b - a), e = a + g * (b - a);
      if (norm(s.point(c) - q) < norm(s.point(e) - q)) b = e;
      else a = c;
    }
    best = std::min(best, norm(s.point(0.5 * (a + b)) - q));
  }
  return best;
}

TEST(ContourDistance, CircleIsClosedForm) {
  ContourDistance cd({Segment::arc({10, 20}, 50, 0.0, 2 * M_PI)});
  std::mt19937 rng(1);
  std::uniform_real_distribution<double> u(-100, 100);
  for (int i = 0; i < 1000; ++i) {
    const Vec2 q{u(rng), u(rng)};
    EXPECT_NEAR(cd.nearest(q).distance, std::fabs(norm(q - Vec2{10, 20}) - 50), 1e-9);
  }
}

TEST(ContourDistance, ArcOutsideItsSweepGoesToTheNearerEnd) {
  // Quarter circle from (1,0) to (0,1) about the origin, counter-clockwise.
  ContourDistance cd({Segment::arc({0, 0}, 1, 0.0, M_PI / 2)});
  EXPECT_NEAR(cd.nearest({2, -1}).distance, std::hypot(1.0, 1.0), 1e-12);
  EXPECT_NEAR(cd.nearest({-1, 3}).distance, std::hypot(1.0, 2.0), 1e-12);
  EXPECT_NEAR(cd.nearest({3, 3}).distance, std::sqrt(18.0) - 1, 1e-12);
  // Clockwise arc over the same quarter, start (0,1).
  ContourDistance cw({Segment::arc({0, 0}, 1, M_PI / 2, -M_PI / 2)});
  EXPECT_NEAR(cw.nearest({3, 3}).distance, std::sqrt(18.0) - 1, 1e-12);
  EXPECT_NEAR(cw.nearest({-1, -1}).distance, std::min(std::hypot(1.0, 2.0), std::hypot(2.0, 1.0)), 1e-12);
}

TEST(ContourDistance, PolylineTakesTheNearestSegment) {
  ContourDistance cd({Segment::line({0, 0}, {10, 0}), Segment::line({10, 0}, {10, 10})});
  EXPECT_NEAR(cd.nearest({5, 3}).distance, 3.0, 1e-12);
  EXPECT_NEAR(cd.nearest({12, 5}).distance, 2.0, 1e-12);
  EXPECT_NEAR(cd.nearest({13, -4}).distance, 5.0, 1e-12);
  EXPECT_EQ(cd.nearest({12, 5}).segment, 1);
}

TEST(ContourDistance, CubicParabolaMatchesBruteForce) {
  // y = 0.001 x^3 - 0.02 x^2 + 0.5 x, x in [-30, 40] (mm scaled to BLU 0.01).
  const Segment s = Segment::cubic_parabola(0.001, -0.02, 0.5, 1.0, -30, 40).scaled(100.0);
  ContourDistance cd({s});
  std::mt19937 rng(2);
  std::uniform_real_distribution<double> ux(-3500, 4500), uy(-6000, 8000);
  for (int i = 0; i < 300; ++i) {
    const Vec2 q{ux(rng), uy(rng)};
    const double got = cd.nearest(q).distance, want = brute_distance(s, q);
    // Certified: never more than kDistanceAccuracy above the true distance, never below.
    EXPECT_LE(got, want + kDistanceAccuracy) << q.x << "," << q.y;
    EXPECT_GE(got, want - 1e-7) << q.x << "," << q.y;
  }
}

TEST(ContourDistance, RandomSplinesMatchBruteForce) {
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> c(-2000, 2000), near(-300, 300);
  for (int piece = 0; piece < 60; ++piece) {
    const Segment s = Segment::spline({c(rng), c(rng)}, {c(rng), c(rng)}, {c(rng), c(rng)},
                                      {c(rng), c(rng)});
    ContourDistance cd({s});
    for (int i = 0; i < 10; ++i) {
      // Points near the curve (where the checker asks) and far from it.
      const Vec2 q = i < 7 ? s.point(std::uniform_real_distribution<double>(0, 1)(rng)) +
                                 Vec2{near(rng), near(rng)}
                           : Vec2{c(rng), c(rng)};
      const double got = cd.nearest(q).distance, want = brute_distance(s, q);
      EXPECT_LE(got, want + kDistanceAccuracy);
      EXPECT_GE(got, want - 1e-7);
      EXPECT_NEAR(norm(cd.nearest(q).foot - q), got, 1e-9);
    }
  }
}

TEST(ContourDistance, FootIsWhereTheNormalMeetsTheCurve) {
  // Kolesnikov's measure: q - foot is normal to the curve at an interior foot.
  const Segment s = Segment::spline({0, 0}, {1000, 200}, {-300, 800}, {100, -200});
  ContourDistance cd({s});
  const ContourFoot f = cd.nearest({300, 600});
  ASSERT_GT(f.u, 0.0);
  ASSERT_LT(f.u, 1.0);
  const Vec2 tangent = s.eval(f.u).d1;
  EXPECT_NEAR(dot(unit(tangent), unit(Vec2{300, 600} - f.foot)), 0.0, 1e-3);
}

}  // namespace
}  // namespace ncinterp::checker
