// The inputs as docs/first-stage.md states them: a reference-point table's span cubics
// pass through their four reference points (so neighbouring spans meet at every point)
// and are exact on cubic data; the G-code subset's modes (G20, G91, I/J and signed R)
// give the stated geometry; both airfoil formats give the same contour, a spline through
// every point scaled by the chord, C2 at its knots, with the trailing edge as corners.
#include <gtest/gtest.h>

#include <fstream>
#include <random>

#include "inputs/contour_inputs.h"
#include "inputs/reference_table.h"
#include "test_helpers.h"

namespace ncinterp::test {
namespace {

using firststage::table_segments;
using firststage::table_span_cubics;

double cubic_at(const firststage::TableSpanCubic& c, double x) { return ((c.a * x + c.b) * x + c.c) * x + c.d; }

TEST(ReferenceTable, SpansPassThroughTheirFourPointsAndMeet) {
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> u(-5.0, 5.0);
  for (int n : {4, 5, 6, 12}) {
    const double x0 = 20.0, h = 7.5;
    std::vector<double> y;
    for (int k = 0; k < n; ++k) y.push_back(u(rng));
    const auto spans = table_span_cubics(x0, h, y);
    const auto segs = table_segments(x0, h, y);
    ASSERT_EQ(spans.size(), static_cast<size_t>(n - 1));
    for (int k = 0; k + 1 < n; ++k) {
      // Points k-1 .. k+2, clamped into the table at its ends.
      const int m = std::clamp(k - 1, 0, n - 4);
      EXPECT_EQ(spans[k].first_point, m);
      for (int j = m; j < m + 4; ++j) EXPECT_NEAR(cubic_at(spans[k], x0 + j * h), y[j], 1e-9) << "span " << k;
      // The segment (local form) is the same cubic over [x_k, x_k+1].
      for (double s : {0.0, 0.3, 1.0}) {
        const Vec2 p = segs[k].point(s);
        EXPECT_NEAR(p.x, x0 + (k + s) * h, 1e-12);
        EXPECT_NEAR(p.y, cubic_at(spans[k], p.x), 1e-9);
      }
    }
  }
}

TEST(ReferenceTable, DifferencesAndExactOnCubicData) {
  // Ordinates of y = 0.01 x^3 - 0.2 x^2 + x + 3: third differences are 6 * 0.01 * h^3,
  // and every span reproduces that cubic.
  const double x0 = -4.0, h = 2.0;
  const auto f = [](double x) { return ((0.01 * x - 0.2) * x + 1.0) * x + 3.0; };
  std::vector<double> y;
  for (int k = 0; k < 9; ++k) y.push_back(f(x0 + k * h));
  const auto d = firststage::table_differences(y);
  ASSERT_EQ(d.size(), 4u);
  EXPECT_NEAR(d[1][2], y[3] - y[2], 1e-12);
  EXPECT_NEAR(d[2][2], y[4] - 2 * y[3] + y[2], 1e-12);
  for (double d3 : d[3]) EXPECT_NEAR(d3, 6 * 0.01 * h * h * h, 1e-9);
  for (const auto& s : table_span_cubics(x0, h, y)) {
    EXPECT_NEAR(s.a, 0.01, 1e-9);
    EXPECT_NEAR(s.b, -0.2, 1e-9);
    EXPECT_NEAR(s.c, 1.0, 1e-9);
    EXPECT_NEAR(s.d, 3.0, 1e-9);
  }
}

TEST(Gcode, SubsetModesGiveTheStatedGeometry) {
  const std::string program =
      "%\n"
      "(inches, then mm)\n"
      "N10 G17 G20 G90 G94\n"
      "N20 G0 X1 Y0 ; rapid to (25.4, 0)\n"
      "N30 G21 G1 X35.4 F300\n"
      "N40 G91 G3 X-10 Y10 I-10 J0 (quarter circle about X25.4 Y0)\n"
      "N50 G90 G2 X15.4 Y0 R-10 (three quarters, the long way)\n"
      "M30\n";
  const firststage::Contour c = firststage::parse_gcode(program, "t.nc");
  ASSERT_EQ(c.segments.size(), 4u);
  EXPECT_TRUE(c.segments[0].rapid);
  EXPECT_NEAR(c.segments[0].end().x, 25.4, 1e-12);
  EXPECT_EQ(c.segments[1].kind(), firststage::SegmentKind::kLine);
  EXPECT_NEAR(c.segments[1].end().x, 35.4, 1e-12);
  const Segment& q = c.segments[2];
  ASSERT_TRUE(q.is_arc());
  EXPECT_NEAR(q.centre().x, 25.4, 1e-9);
  EXPECT_NEAR(q.centre().y, 0.0, 1e-9);
  EXPECT_NEAR(q.sweep(), M_PI / 2, 1e-9);
  EXPECT_NEAR(q.end().y, 10.0, 1e-9);
  const Segment& l = c.segments[3];  // clockwise from (25.4, 10) to (15.4, 0), |R| = 10, long way
  ASSERT_TRUE(l.is_arc());
  EXPECT_NEAR(l.radius(), 10.0, 1e-9);
  EXPECT_NEAR(l.sweep(), -1.5 * M_PI, 1e-9);
  EXPECT_NEAR(l.centre().x, 25.4, 1e-9);
  EXPECT_NEAR(l.centre().y, 0.0, 1e-9);
  EXPECT_EQ(l.source_line, 7);
}

TEST(Airfoil, BothFormatsOneSplineThroughEveryPointC2WithCornersAtTheTrailingEdge) {
  const std::string dir = NCINTERP_EXAMPLES_DIR;
  firststage::InputOptions io;
  io.airfoil_chord_mm = 250.0;
  const Contour selig = firststage::read_contour(dir + "/naca2412_selig.dat", io);
  const Contour led = firststage::read_contour(dir + "/naca2412_lednicer.dat", io);
  ASSERT_EQ(selig.segments.size(), led.segments.size());
  for (size_t i = 0; i < selig.segments.size(); ++i)
    for (double s : {0.0, 0.5, 1.0}) {
      EXPECT_NEAR(selig.segments[i].point(s).x, led.segments[i].point(s).x, 1e-9);
      EXPECT_NEAR(selig.segments[i].point(s).y, led.segments[i].point(s).y, 1e-9);
    }
  // The Selig file's points, read here, are the knots (times the chord).
  std::ifstream in(dir + "/naca2412_selig.dat");
  std::string name;
  std::getline(in, name);
  std::vector<Vec2> pts;
  for (double x, y; in >> x >> y;) pts.push_back({250.0 * x, 250.0 * y});
  const size_t pieces = selig.segments.size() - 1;  // the last segment closes the trailing edge
  ASSERT_EQ(pieces + 1, pts.size());
  for (size_t i = 0; i < pieces; ++i) {
    EXPECT_NEAR(selig.segments[i].start().x, pts[i].x, 1e-9);
    EXPECT_NEAR(selig.segments[i].start().y, pts[i].y, 1e-9);
    EXPECT_NEAR(selig.segments[i].end().x, pts[i + 1].x, 1e-9);
    EXPECT_NEAR(selig.segments[i].end().y, pts[i + 1].y, 1e-9);
  }
  // C2 in arc length at every interior knot: equal unit tangents and equal curvature
  // vectors (the pieces' parameters differ in scale, so compare geometric quantities).
  for (size_t i = 1; i < pieces; ++i) {
    const auto a = selig.segments[i - 1].eval(1.0), b = selig.segments[i].eval(0.0);
    const Vec2 ta = firststage::unit(a.d1), tb = firststage::unit(b.d1);
    EXPECT_NEAR(ta.x, tb.x, 1e-9);
    EXPECT_NEAR(ta.y, tb.y, 1e-9);
    const double ka = firststage::cross(a.d1, a.d2) / std::pow(firststage::norm(a.d1), 3);
    const double kb = firststage::cross(b.d1, b.d2) / std::pow(firststage::norm(b.d1), 3);
    EXPECT_NEAR(ka, kb, 1e-6 * (1 + std::fabs(ka))) << "knot " << i;
  }
  // Trailing edge: the closing line meets the spline's ends at corners.
  EXPECT_EQ(selig.segments.back().kind(), firststage::SegmentKind::kLine);
  EXPECT_FALSE(firststage::smooth_joint(selig.segments[pieces - 1], selig.segments.back()));
  EXPECT_GT(firststage::joint_turn(selig.segments.back(), selig.segments.front()), 0.1);
}

}  // namespace
}  // namespace ncinterp::test
