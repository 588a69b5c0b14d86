// The fixed-point arithmetic, and every method in fixed point against the same method in
// double: the difference must come from rounding to the word only, so it shrinks with
// the quantum and stays within a few quanta per period.
#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <stdexcept>

#include "circle_runs.h"
#include "fixed_arith.h"
#include "line_run.h"
#include "real_point.h"

namespace ncinterp::sampled {
namespace {

TEST(FixedPoint, FormatPutsTheBinaryPointJustAboveTheMagnitude) {
  const FixedFormat f = FixedFormat::for_magnitude(20.0, 32);  // 16 <= 20 < 32: 5 integer bits
  EXPECT_EQ(f.frac_bits, 26);
  FixedArith a(f);
  EXPECT_NO_THROW(a.from_real(20.0));
  EXPECT_NO_THROW(a.from_real(-31.9));
  EXPECT_THROW(a.from_real(32.0), std::overflow_error);
  EXPECT_DOUBLE_EQ(a.quantum(), std::ldexp(1.0, -26));
}

TEST(FixedPoint, ProductsRoundToTheNearestQuantum) {
  FixedArith a(FixedFormat{32, 0});  // quantum 1: raw values are the numbers
  EXPECT_EQ(a.mul(a.coef(0.5), 3), 2);    // 1.5: ties go up
  EXPECT_EQ(a.mul(a.coef(0.5), -3), -1);  // -1.5: ties go up
  EXPECT_EQ(a.mul(a.coef(0.25), -3), -1); // -0.75
  EXPECT_EQ(a.half(5), 3);
  EXPECT_EQ(a.half(-5), -2);
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> coef(-0.9, 0.9);
  std::uniform_int_distribution<int64_t> value(-(int64_t{1} << 30), int64_t{1} << 30);
  for (int i = 0; i < 10000; ++i) {
    const double c = coef(rng) * std::pow(10.0, -(i % 9));
    const int64_t v = value(rng);
    const double exact = c * static_cast<double>(v);
    // Half a quantum of rounding plus the constant's own error (B - 1 significant bits).
    ASSERT_LE(std::fabs(a.mul(a.coef(c), v) - exact), 0.5 + std::fabs(exact) * std::ldexp(1.0, -31) + 1e-6)
        << "c " << c << " v " << v;
  }
}

TEST(FixedPoint, SmallConstantsKeepTheirSignificantBits) {
  FixedArith a(FixedFormat{24, 10});
  for (double c : {5e-9, 0.5e-4 * 1e-4, 0.3, 1.0}) {
    const FixedArith::Coef k = a.coef(c);
    EXPECT_LE(std::fabs(std::ldexp(static_cast<double>(k.mantissa), -k.shift) / c - 1), std::ldexp(1.0, -23)) << c;
  }
}

TEST(FixedPoint, LeavingTheWordThrows) {
  FixedArith a(FixedFormat{16, 0});
  EXPECT_THROW(a.add(32000, 1000), std::overflow_error);
  EXPECT_THROW(a.sub(-32000, 1000), std::overflow_error);
  EXPECT_EQ(a.add(32000, 767), 32767);
}

TEST(FixedPoint, EveryCircleMethodFollowsDoubleWithinItsWordLength) {
  const double r = 10.0, h = 0.01;
  for (Method m : kCircleMethods) {
    const QuarterRun d = run_quarter(m, r, h, Starter::kK7, Arithmetic::double_precision());
    const QuarterRun f32 = run_quarter(m, r, h, Starter::kK7, Arithmetic::fixed(32));
    const QuarterRun f48 = run_quarter(m, r, h, Starter::kK7, Arithmetic::fixed(48));
    ASSERT_EQ(f32.points.size(), d.points.size()) << method_name(m);
    const double periods = static_cast<double>(d.points.size() - 1);
    // At most a few quanta of rounding per period (2 to 4 rounded products each).
    EXPECT_LE(max_distance(f32.points, d.points), 4 * periods * f32.quantum) << method_name(m);
    EXPECT_LE(max_distance(f48.points, d.points), 4 * periods * f48.quantum) << method_name(m);
    // and it is rounding: 16 more bits make it thousands of times smaller.
    EXPECT_LT(max_distance(f48.points, d.points), max_distance(f32.points, d.points) / 1000) << method_name(m);
    EXPECT_NEAR(f32.max_radial_error, d.max_radial_error, 4 * periods * f32.quantum) << method_name(m);
  }
}

TEST(FixedPoint, L1FollowsDoubleWithinItsWordLength) {
  const LineRun d = run_line(10.0, 0.5, 0.001, Arithmetic::double_precision());
  const LineRun f = run_line(10.0, 0.5, 0.001, Arithmetic::fixed(32));
  const double periods = static_cast<double>(d.points.size() - 1);
  // Each h_k is off by at most half a quantum, and that adds up period by period.
  EXPECT_LE(max_distance(f.points, d.points), periods * f.quantum * std::sqrt(0.5) + f.quantum);
  EXPECT_GT(f.max_deviation, 0.0);
}

}  // namespace
}  // namespace ncinterp::sampled
