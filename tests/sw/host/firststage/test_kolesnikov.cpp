// Kolesnikov's worked case (paper 004, eq. 29): the chord from (0, 0) to (D, y1) of the
// parabola through (-D, -y2), (0, 0), (D, y1) has its maximum normal error at x = D/2,
// beta_max = (y2 - y1) D / (8 sqrt(y1^2 + D^2)). Checked against the first stage's exact
// deviation and against a brute-force normal distance computed here.
#include <gtest/gtest.h>

#include <cmath>

#include "chords/chord_deviation.h"

namespace ncinterp::firststage {
namespace {

double brute_force_normal_error(double a0, double a1, double d, double* at) {
  // Chord y = k x on [0, D]; along the normal of the parabola at x: distance to the line.
  const double k = (a0 * d * d + a1 * d) / d;
  double worst = 0.0;
  for (int i = 0; i <= 200000; ++i) {
    const double x = d * i / 200000.0;
    const double y = a0 * x * x + a1 * x, s = 2 * a0 * x + a1;
    const double nx = -s / std::hypot(1, s), ny = 1 / std::hypot(1, s);
    // Solve (x + t nx, y + t ny) on y = k x.
    const double t = (k * x - y) / (ny - k * nx);
    if (std::fabs(t) > worst) worst = std::fabs(t), *at = x;
  }
  return worst;
}

TEST(Kolesnikov, WorkedCaseEq29) {
  const double cases[][3] = {{10.0, 2.0, 5.0}, {1.0, 0.3, 0.4}, {50.0, -3.0, 4.0}, {7.0, 1.5, 1.6}};
  for (const auto& c : cases) {
    const double d = c[0], y1 = c[1], y2 = c[2];
    const double a0 = (y1 - y2) / (2 * d * d), a1 = (y1 + y2) / (2 * d);
    const double expected = std::fabs((y2 - y1) * d / (8 * std::sqrt(y1 * y1 + d * d)));
    const Segment seg = Segment::cubic_parabola(0.0, a0, a1, 0.0, 0.0, d);
    const Span span(&seg, 1);
    const double got = chord_deviation(span, {0, 0}, {d, y1}, 0.0, 1.0);
    EXPECT_NEAR(got, expected, 1e-12 * (1 + expected));
    double at = 0;
    const double brute = brute_force_normal_error(a0, a1, d, &at);
    EXPECT_NEAR(brute, expected, 1e-9 * (1 + expected));
    EXPECT_NEAR(at, d / 2, d * 1e-5);
  }
}

}  // namespace
}  // namespace ncinterp::firststage
