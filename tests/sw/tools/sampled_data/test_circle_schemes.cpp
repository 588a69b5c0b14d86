// K1..K7 against closed forms derived independently of the code (docs/sampled-data.md,
// section "Closed forms"): each scheme is a linear map of (X, Y), so what it keeps or how
// it grows the radius follows from its matrix, not from running it.
#include <gtest/gtest.h>

#include <cmath>
#include <complex>
#include <vector>

#include "circle_scheme.h"
#include "float_arith.h"

namespace ncinterp::sampled {
namespace {

using Arith = FloatArith<double>;
using Scheme = CircleScheme<Arith>;
using Point = Scheme::Point;

// The reference points of `periods` periods from (r, 0), start included.
std::vector<Point> run(Method m, double h, int periods, Starter starter = Starter::kK7, double r = 10.0) {
  Arith a;
  Scheme s(m, h, starter, a);
  s.start({r, 0.0});
  std::vector<Point> pts{s.point()};
  for (int i = 0; i < periods; ++i) pts.push_back(s.step());
  return pts;
}

double radius(Point p) { return std::hypot(p.x, p.y); }

const double kHs[] = {1e-3, 0.05, 0.3};

TEST(CircleSchemes, K1GrowsTheRadiusBySqrtOnePlusHSquaredEveryPeriod) {
  for (double h : kHs) {
    const auto pts = run(Method::kK1, h, 200);
    for (size_t i = 1; i < pts.size(); ++i)
      ASSERT_NEAR(radius(pts[i]) / radius(pts[i - 1]), std::sqrt(1 + h * h), 1e-14) << "h " << h << " period " << i;
  }
}

TEST(CircleSchemes, K7GrowsTheRadiusBySqrtOnePlusHToTheFourthOver4EveryPeriod) {
  for (double h : kHs) {
    const auto pts = run(Method::kK7, h, 200);
    for (size_t i = 1; i < pts.size(); ++i)
      ASSERT_NEAR(radius(pts[i]) / radius(pts[i - 1]), std::sqrt(1 + h * h * h * h / 4), 1e-14) << "h " << h;
  }
}

TEST(CircleSchemes, K4KeepsXSquaredPlusYSquaredPlusHXY) {
  for (double h : kHs) {
    const auto pts = run(Method::kK4, h, 500);
    const auto q = [h](Point p) { return p.x * p.x + p.y * p.y + h * p.x * p.y; };
    for (const Point& p : pts) ASSERT_NEAR(q(p) / q(pts[0]), 1.0, 1e-12) << "h " << h;
  }
}

// K5's two periods (eq. 3 then eq. 4) make the map [[1-2h^2, 2h-2h^3], [-2h, 1-2h^2]]:
// even points keep X^2 + (1-h^2) Y^2, odd points (1-h^2) X^2 + Y^2.
TEST(CircleSchemes, K5KeepsOneEllipseOnEvenAndItsMirrorOnOddPeriods) {
  for (double h : kHs) {
    const auto pts = run(Method::kK5, h, 500);
    const double even0 = pts[0].x * pts[0].x + (1 - h * h) * pts[0].y * pts[0].y;
    const double odd0 = (1 - h * h) * pts[1].x * pts[1].x + pts[1].y * pts[1].y;
    for (size_t i = 0; i < pts.size(); ++i) {
      const Point p = pts[i];
      if (i % 2 == 0)
        ASSERT_NEAR((p.x * p.x + (1 - h * h) * p.y * p.y) / even0, 1.0, 1e-12) << "h " << h << " period " << i;
      else
        ASSERT_NEAR(((1 - h * h) * p.x * p.x + p.y * p.y) / odd0, 1.0, 1e-12) << "h " << h << " period " << i;
    }
  }
}

// K6 as written moves X by 0.5h + 0.5h = h per period but Y by 2h: its map
// [[1-h^2, h-h^3/2], [-2h, 1-h^2]] keeps 2 X^2 + (1 - h^2/2) Y^2, an ellipse whose axes
// differ by sqrt(2) whatever h is.
TEST(CircleSchemes, K6AsWrittenKeepsAnEllipseNotTheCircle) {
  for (double h : kHs) {
    const auto pts = run(Method::kK6, h, static_cast<int>(2 / h) + 10);  // past the Y axis
    const auto q = [h](Point p) { return 2 * p.x * p.x + (1 - h * h / 2) * p.y * p.y; };
    double largest = 0;
    for (const Point& p : pts) {
      ASSERT_NEAR(q(p) / q(pts[0]), 1.0, 1e-12) << "h " << h;
      largest = std::max(largest, radius(p));
    }
    EXPECT_GT(largest / 10.0, 1.4) << "h " << h;  // reaches ~sqrt(2) R on the Y axis
  }
}

// K3: z+ = z- - 2ih z (z = X + iY) keeps |z_n|^2 + |z_n+1|^2 + 2h Im(z_n+1 conj z_n).
TEST(CircleSchemes, K3KeepsItsTwoStepInvariant) {
  for (double h : kHs) {
    for (Starter st : {Starter::kK1, Starter::kK7}) {
      const auto pts = run(Method::kK3, h, 500, st);
      const auto q = [h](Point a, Point b) {
        return a.x * a.x + a.y * a.y + b.x * b.x + b.y * b.y + 2 * h * (b.y * a.x - b.x * a.y);
      };
      const double q0 = q(pts[0], pts[1]);
      for (size_t i = 1; i + 1 < pts.size(); ++i) ASSERT_NEAR(q(pts[i], pts[i + 1]) / q0, 1.0, 1e-12) << "h " << h;
    }
  }
}

// K2 with dX the last period's increment is the two-step Adams-Bashforth rule
// z+ = z - ih (1.5 z - 0.5 z-): z_n = a r1^n + b r2^n, r the roots of
// r^2 - (1 - 1.5ih) r - 0.5ih = 0, a and b fitted to the first two points.
TEST(CircleSchemes, K2FollowsTheClosedFormOfItsTwoStepRecurrence) {
  using C = std::complex<double>;
  const C i(0, 1);
  for (double h : kHs) {
    const auto pts = run(Method::kK2, h, 300);
    const C z0(pts[0].x, pts[0].y), z1(pts[1].x, pts[1].y);
    const C b = -(1.0 - 1.5 * i * h), c = -0.5 * i * h;
    const C disc = std::sqrt(b * b - 4.0 * c);
    const C r1 = (-b + disc) / 2.0, r2 = (-b - disc) / 2.0;
    const C bb = (z1 - r1 * z0) / (r2 - r1), aa = z0 - bb;
    for (size_t n = 0; n < pts.size(); ++n) {
      const C z = aa * std::pow(r1, double(n)) + bb * std::pow(r2, double(n));
      ASSERT_NEAR(std::abs(z - C(pts[n].x, pts[n].y)), 0.0, 1e-10 * 10.0) << "h " << h << " period " << n;
    }
  }
}

TEST(CircleSchemes, K2AndK3TakeTheirFirstPeriodFromTheStarter) {
  const double h = 0.05;
  for (Method m : {Method::kK2, Method::kK3}) {
    const Point by_k1 = run(m, h, 1, Starter::kK1)[1], k1 = run(Method::kK1, h, 1)[1];
    const Point by_k7 = run(m, h, 1, Starter::kK7)[1], k7 = run(Method::kK7, h, 1)[1];
    EXPECT_EQ(by_k1.x, k1.x);
    EXPECT_EQ(by_k1.y, k1.y);
    EXPECT_EQ(by_k7.x, k7.x);
    EXPECT_EQ(by_k7.y, k7.y);
  }
}

TEST(CircleSchemes, ClockwiseForPositiveH) {
  for (Method m : kCircleMethods) {
    const Point p = run(m, 0.01, 1)[1];
    EXPECT_LT(p.y, 0) << method_name(m);  // from (R, 0) clockwise: Y goes negative
  }
}

// The operations of one steady period, counted by the arithmetic.
TEST(CircleSchemes, OperationsPerPeriod) {
  struct Expected {
    Method m;
    uint64_t mul, add, shift;
  };
  const Expected expected[] = {{Method::kK1, 2, 2, 0}, {Method::kK2, 2, 4, 2}, {Method::kK3, 2, 2, 0},
                               {Method::kK4, 2, 2, 0}, {Method::kK5, 2, 2, 0}, {Method::kK6, 3, 3, 0},
                               {Method::kK7, 4, 4, 0}};
  for (const Expected& e : expected) {
    Arith a;
    Scheme s(e.m, 0.01, Starter::kK7, a);
    s.start({1.0, 0.0});
    s.step();
    s.step();
    const OpCount before = a.ops();
    s.step();
    const OpCount d = a.ops() - before;
    EXPECT_EQ(d.mul, e.mul) << method_name(e.m);
    EXPECT_EQ(d.add, e.add) << method_name(e.m);
    EXPECT_EQ(d.shift, e.shift) << method_name(e.m);
  }
}

}  // namespace
}  // namespace ncinterp::sampled
