// The independent checker itself: its fast search gives exactly the brute-force result,
// it measures known deviations (an inscribed polygon's sagitta, a vertex pushed off the
// curve) and it catches a first-stage tape with one vertex moved by a few BLU. Without
// these, a checker that always reports 0 would let every guarantee test pass.
#include <gtest/gtest.h>

#include <limits>
#include <random>

#include "test_helpers.h"

namespace ncinterp::test {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

double seg_dist(P2 p, P2 a, P2 b) {
  const double vx = b.x - a.x, vy = b.y - a.y, l2 = vx * vx + vy * vy;
  const double t = l2 > 0 ? std::clamp(((p.x - a.x) * vx + (p.y - a.y) * vy) / l2, 0.0, 1.0) : 0.0;
  return std::hypot(p.x - (a.x + t * vx), p.y - (a.y + t * vy));
}

// The same two measures by brute force over every pair (no corners: the zones are the
// curve's two ends, as in check_path).
CheckResult brute_force(const std::vector<P2>& curve, const std::vector<P2>& path, double step) {
  CheckResult r;
  double len = 0;
  for (size_t i = 1; i < curve.size(); ++i) len += std::hypot(curve[i].x - curve[i - 1].x, curve[i].y - curve[i - 1].y);
  const double spacing = len / (curve.size() - 1);
  auto path_dist = [&](P2 c) {
    double d = kInf;
    for (size_t j = 0; j + 1 < path.size(); ++j) d = std::min(d, seg_dist(c, path[j], path[j + 1]));
    return d;
  };
  auto nearest_vertex = [&](P2 z) {
    double d = kInf;
    for (const P2& v : path) d = std::min(d, std::hypot(v.x - z.x, v.y - z.y));
    return d;
  };
  const double front = nearest_vertex(curve.front()) + spacing, back = nearest_vertex(curve.back()) + spacing;
  for (size_t i = 0; i < curve.size(); ++i) {
    const P2 c = curve[i];
    double best = kInf;
    if (std::hypot(c.x - curve.front().x, c.y - curve.front().y) <= front ||
        std::hypot(c.x - curve.back().x, c.y - curve.back().y) <= back) {
      best = path_dist(c);
    } else {
      const P2 a = curve[i - 1], b = curve[i + 1];
      const double tl = std::hypot(b.x - a.x, b.y - a.y), nx = -(b.y - a.y) / tl, ny = (b.x - a.x) / tl;
      for (size_t j = 0; j + 1 < path.size(); ++j) {
        const double ex = path[j + 1].x - path[j].x, ey = path[j + 1].y - path[j].y;
        const double den = nx * ey - ny * ex;
        if (std::fabs(den) < 1e-15) continue;
        const double ax = path[j].x - c.x, ay = path[j].y - c.y;
        const double t = (ax * ny - ay * nx) / den;
        if (t < -1e-12 || t > 1 + 1e-12) continue;
        best = std::min(best, std::fabs((ax * ey - ay * ex) / den));
      }
      if (!std::isfinite(best)) {
        ++r.unmatched;
        continue;
      }
    }
    r.normal_max = std::max(r.normal_max, best);
  }
  for (size_t j = 0; j + 1 < path.size(); ++j) {
    const P2 a = path[j], b = path[j + 1];
    const long parts = std::max(1L, static_cast<long>(std::ceil(std::hypot(b.x - a.x, b.y - a.y) / step)));
    for (long q = j == 0 ? 0 : 1; q <= parts; ++q) {
      const double f = static_cast<double>(q) / parts;
      const P2 p{a.x + f * (b.x - a.x), a.y + f * (b.y - a.y)};
      double d = kInf;
      for (size_t i = 0; i + 1 < curve.size(); ++i) d = std::min(d, seg_dist(p, curve[i], curve[i + 1]));
      r.path_max = std::max(r.path_max, d);
    }
  }
  return r;
}

TEST(IndependentChecker, EqualsBruteForceOnRandomWigglyPaths) {
  std::mt19937 rng(99);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  for (int trial = 0; trial < 40; ++trial) {
    // A wavy curve and a path of its samples, each pushed off by up to 0.02.
    const double amp = 0.5 + 0.5 * u(rng), freq = 2 + u(rng);
    const auto curve = sample_curve([&](double s) {
      return P2{10 * s, amp * std::sin(freq * 10 * s)};
    }, 1500);
    std::vector<P2> path;
    const int n = 20 + trial;
    for (int k = 0; k <= n; ++k) {
      const double s = static_cast<double>(k) / n;
      path.push_back({10 * s + 0.01 * u(rng), amp * std::sin(freq * 10 * s) + 0.02 * u(rng)});
    }
    const CheckResult fast = check_path(curve, path, 0.01);
    const CheckResult slow = brute_force(curve, path, 0.01);
    EXPECT_EQ(fast.normal_max, slow.normal_max) << "trial " << trial;
    EXPECT_EQ(fast.path_max, slow.path_max) << "trial " << trial;
    EXPECT_EQ(fast.unmatched, slow.unmatched) << "trial " << trial;
    EXPECT_GT(fast.normal_max, 0.005);
  }
}

TEST(IndependentChecker, InscribedPolygonSagittaAndOneVertexOff) {
  const double r = 10.0;
  const int n = 37;
  const auto curve = sample_curve([&](double s) {
    return P2{r * std::cos(2 * M_PI * s), r * std::sin(2 * M_PI * s)};
  }, 400000);
  std::vector<P2> polygon;
  for (int k = 0; k <= n; ++k) polygon.push_back({r * std::cos(2 * M_PI * k / n), r * std::sin(2 * M_PI * k / n)});
  const double sagitta = r * (1 - std::cos(M_PI / n));
  CheckResult c = check_path(curve, polygon, 1e-3);
  EXPECT_NEAR(c.normal_max, sagitta, 1e-8);
  EXPECT_NEAR(c.path_max, sagitta, 1e-6);
  EXPECT_EQ(c.unmatched, 0);
  // Vertex 12 pushed 0.1 outward (beyond the sagitta, 0.036): both measures see it there.
  polygon[12] = {(r + 0.1) * std::cos(2 * M_PI * 12 / n), (r + 0.1) * std::sin(2 * M_PI * 12 / n)};
  c = check_path(curve, polygon, 1e-3);
  EXPECT_NEAR(c.normal_max, 0.1, 1e-5);  // the nearest curve sample is up to 1e-4 mm beside it
  EXPECT_NEAR(c.path_max, 0.1, 1e-9);
  EXPECT_NEAR(c.normal_worst.x, r * std::cos(2 * M_PI * 12 / n), 1e-3);
  EXPECT_NEAR(c.path_worst.y, (r + 0.1) * std::sin(2 * M_PI * 12 / n), 1e-9);
}

TEST(IndependentChecker, CatchesATapeWithOneVertexThreeBluOff) {
  // A correct first-stage path passes; the same path with one chord vertex moved 3 BLU
  // outward fails the delta' bound the guarantee tests use.
  FirstStageOptions o;
  const double r = 20.0;
  const Contour c = contour_of({r, 0}, {Segment::arc({0, 0}, r, 0.0, 2 * M_PI)});
  FirstStageResult res = firststage::run_first_stage(c, o);
  const auto curve = sample_curve([&](double s) {
    return P2{r * std::cos(2 * M_PI * s), r * std::sin(2 * M_PI * s)};
  }, 200000);
  const double dprime = o.tol_mm - o.budget_blu * o.blu_mm;
  EXPECT_LE(check_path(curve, path_mm(res, o.blu_mm), o.tol_mm / 8).normal_max, dprime + 2e-6);
  auto& m = res.moves[res.moves.size() / 2].to;
  const double len = std::hypot(static_cast<double>(m.x), static_cast<double>(m.y));
  m.x += std::llround(3 * m.x / len);
  m.y += std::llround(3 * m.y / len);
  const CheckResult bad = check_path(curve, path_mm(res, o.blu_mm), o.tol_mm / 8);
  EXPECT_GT(bad.normal_max, dprime + 0.001);
  EXPECT_GT(bad.path_max, dprime + 0.001);
}

TEST(IndependentChecker, DistanceRangeOfAnOffsetSquare) {
  // Points on a unit square's sides against the square grown by 0.5: all 0.5 away, except
  // none nearer; the corners' points are 0.5 from the grown square's sides.
  const std::vector<std::vector<P2>> grown{{{-0.5, -0.5}, {1.5, -0.5}, {1.5, 1.5}, {-0.5, 1.5}, {-0.5, -0.5}}};
  std::vector<P2> pts;
  for (int k = 0; k <= 100; ++k) pts.push_back({k / 100.0, 0.0});
  DistanceRange d = distance_range(pts, grown);
  EXPECT_DOUBLE_EQ(d.min, 0.5);
  EXPECT_DOUBLE_EQ(d.max, 0.5);
  pts.push_back({0.5, 0.5});  // the centre: 1.0 from every side
  d = distance_range(pts, grown);
  EXPECT_DOUBLE_EQ(d.max, 1.0);
  EXPECT_DOUBLE_EQ(d.at_max.x, 0.5);
}

}  // namespace
}  // namespace ncinterp::test
