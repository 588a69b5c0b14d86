// The measurements: quarter-circle errors against closed forms, the paper's formulas where
// they hold (and K7's, where it does not), drift over turns, the one-period error's
// order, L1's end point, the order fit, the hardware DDA comparison and a small study.
#include <gtest/gtest.h>

#include <cmath>

#include "circle_runs.h"
#include "dda_comparison.h"
#include "line_run.h"
#include "method_study.h"
#include "order_fit.h"

namespace ncinterp::sampled {
namespace {

constexpr double kPi = 3.14159265358979323846;

QuarterRun quarter(Method m, double h, double r = 10.0, Starter s = Starter::kK7) {
  return run_quarter(m, r, h, s, Arithmetic::double_precision());
}

double periods(const QuarterRun& q) { return static_cast<double>(q.points.size() - 1); }

// K1 and K7 only grow, by a known factor per period: the largest error is at the end.
TEST(Measurements, K1AndK7QuarterErrorsEqualTheirGrowthOverTheQuarter) {
  for (double h : {1e-3, 1e-2, 1e-1}) {
    const QuarterRun k1 = quarter(Method::kK1, h), k7 = quarter(Method::kK7, h);
    EXPECT_NEAR(k1.max_radial_error / (10.0 * (std::pow(1 + h * h, periods(k1) / 2) - 1)), 1.0, 1e-9) << h;
    // K7's error is small enough (2e-10 R at h = 1e-3) for double round-off to show.
    EXPECT_NEAR(k7.max_radial_error / (10.0 * (std::pow(1 + h * h * h * h / 4, periods(k7) / 2) - 1)), 1.0, 1e-3)
        << h;
  }
}

// From the invariants (test_circle_schemes.cpp): K4's ellipse is farthest from the circle
// at 45 degrees, R (1/sqrt(1 - h/2) - 1); K5's at the axes, R (1/sqrt(1 - h^2) - 1); K6's
// on the Y axis, R (sqrt(2 / (1 - h^2/2)) - 1). Points need not land exactly there.
TEST(Measurements, K4K5K6QuarterErrorsReachTheirEllipses) {
  for (double h : {1e-3, 1e-2}) {
    const double k4 = 10.0 * (1 / std::sqrt(1 - h / 2) - 1);
    const double k5 = 10.0 * (1 / std::sqrt(1 - h * h) - 1);
    const double k6 = 10.0 * (std::sqrt(2 / (1 - h * h / 2)) - 1);
    EXPECT_LE(quarter(Method::kK4, h).max_radial_error, k4 * (1 + 1e-9));
    EXPECT_GE(quarter(Method::kK4, h).max_radial_error, k4 * 0.99);
    EXPECT_NEAR(quarter(Method::kK4, h).worst_angle_deg, 45.0, 1.0);
    EXPECT_LE(quarter(Method::kK5, h).max_radial_error, k5 * (1 + 1e-6));
    EXPECT_GE(quarter(Method::kK5, h).max_radial_error, k5 * 0.99);
    EXPECT_LE(quarter(Method::kK6, h).max_radial_error, k6 * (1 + 1e-9));
    EXPECT_GE(quarter(Method::kK6, h).max_radial_error, k6 * 0.99);
  }
}

// K3 started with one K7 period: the two roots of its recurrence have modulus 1; the start
// puts R h^4/16 into the parasitic one, so |P| beats between R and R (1 + h^4/8). Started
// with K1 the parasitic part is R h^2/4: the error is h^2/2 R.
TEST(Measurements, K3ErrorIsSetByItsStart) {
  for (double h : {1e-2, 5e-2}) {
    const double k7_start = quarter(Method::kK3, h, 10.0, Starter::kK7).max_radial_error;
    const double k1_start = quarter(Method::kK3, h, 10.0, Starter::kK1).max_radial_error;
    EXPECT_NEAR(k7_start / (10.0 * std::pow(h, 4) / 8), 1.0, 0.02) << h;
    EXPECT_NEAR(k1_start / (10.0 * h * h / 2), 1.0, 0.02) << h;
  }
}

TEST(Measurements, PaperFormulasThatHold) {
  const double h = 1e-3, r = 10.0;
  EXPECT_NEAR(quarter(Method::kK1, h).max_radial_error / (0.25 * kPi * h * r), 1.0, 0.01);
  EXPECT_NEAR(quarter(Method::kK4, h).max_radial_error / (0.25 * h * r), 1.0, 0.01);
  EXPECT_NEAR(quarter(Method::kK5, h).max_radial_error / (0.5 * h * h * r), 1.0, 0.01);
}

// The paper: K7's E_r = 0.0625 pi R h^2. Measured: the same constant with h^3.
TEST(Measurements, K7IsThirdOrderNotSecond) {
  for (double h : {1e-3, 1e-2}) {
    const double e = quarter(Method::kK7, h).max_radial_error;
    EXPECT_NEAR(e / (0.0625 * kPi * 10.0 * h * h * h), 1.0, 0.02) << h;
    EXPECT_LT(e, 0.0625 * kPi * 10.0 * h * h / 50) << h;
  }
}

TEST(Measurements, PathErrorIncludesTheChordSag) {
  const double h = 0.05, r = 10.0;
  const QuarterRun q = quarter(Method::kK3, h, r);
  EXPECT_LT(q.max_radial_error, 1e-5);
  EXPECT_GE(q.max_path_error, r * (1 - std::cos(h / 2)) * 0.999);
  EXPECT_LE(q.max_path_error, r * (1 - std::cos(h / 2)) * 1.001 + q.max_radial_error);
}

TEST(Measurements, OnlyK1K2AndK7DriftFromTurnToTurn) {
  const double h = 0.02;
  for (Method m : kCircleMethods) {
    const TurnsRun t = run_turns(m, 10.0, h, 5, Starter::kK7, Arithmetic::double_precision());
    ASSERT_EQ(t.max_error_per_turn.size(), 5u);
    const bool drifts = m == Method::kK1 || m == Method::kK2 || m == Method::kK7;
    if (drifts)
      EXPECT_GT(t.max_error_per_turn.back(), 3 * t.max_error_per_turn.front()) << method_name(m);
    else
      EXPECT_LT(t.max_error_per_turn.back(), 1.01 * t.max_error_per_turn.front()) << method_name(m);
  }
}

// Halving h divides the one-period error by 2^p, p the local order.
TEST(Measurements, OnePeriodErrorOrders) {
  const std::pair<Method, double> orders[] = {{Method::kK1, 2}, {Method::kK2, 3}, {Method::kK3, 3}, {Method::kK4, 2},
                                              {Method::kK5, 2}, {Method::kK6, 1}, {Method::kK7, 3}};
  for (const auto& [m, p] : orders) {
    const double ratio = local_step_error(m, 2e-3) / local_step_error(m, 1e-3);
    EXPECT_NEAR(std::log2(ratio), p, 0.05) << method_name(m);
  }
}

TEST(Measurements, L1EndsShortByTheRemainderOfTheLastStep) {
  // 1/h = 10.4: ten steps of 0.096154 L leave 0.038462 L.
  const double h = 1 / 10.4, length = 10.0;
  const LineRun run = run_line(length, 0.5, h, Arithmetic::double_precision());
  EXPECT_EQ(run.points.size(), 11u);
  EXPECT_NEAR(run.endpoint_error, length * (1 - 10 * h), 1e-12);
  EXPECT_LT(run.max_deviation, 1e-13);
  const LineRun whole = run_line(length, 0.5, 0.125, Arithmetic::double_precision());
  EXPECT_LT(whole.endpoint_error, 1e-13);
}

TEST(Measurements, OrderFitRecoversAPowerLaw) {
  std::vector<double> h, e;
  for (double x : {1e-4, 1e-3, 3e-3, 1e-2}) {
    h.push_back(x);
    e.push_back(0.196 * x * x * x);
  }
  const OrderFit f = fit_order(h, e);
  ASSERT_TRUE(f.valid);
  EXPECT_NEAR(f.order, 3.0, 1e-9);
  EXPECT_NEAR(f.constant, 0.196, 1e-9);
  EXPECT_LT(f.max_residual_decades, 1e-9);
  EXPECT_FALSE(fit_order({1e-3}, {1.0}).valid);
  EXPECT_FALSE(fit_order({1e-3, 1e-3}, {1.0, 2.0}).valid);
}

// The golden circle DDA on a full quadrant: within docs/circle-dda.md's 0.88 BLU bound,
// R pulses per axis, fewer than 2^(k+1) iterations.
TEST(Comparison, HardwareDdaQuadrant) {
  const DdaQuadrant q = run_hardware_dda_quadrant(1000);
  EXPECT_EQ(q.k, 10u);
  EXPECT_EQ(q.pulses, 2000u);
  EXPECT_LT(q.iterations, 2048u);
  EXPECT_GT(q.iterations, 1500u);  // about (pi/2) 2^k
  EXPECT_LE(q.max_radial_error_blu, 0.88);
  EXPECT_GT(q.max_radial_error_blu, 0.3);
}

TEST(Comparison, SampledMethodMeetsOneBluWithTheShortestWord) {
  const int64_t r = 1000;
  const SampledForOneBlu k5 = sampled_for_one_blu(Method::kK5, r, Starter::kK7);
  ASSERT_TRUE(k5.reached);
  EXPECT_LE(k5.path_error_double_blu, 0.5);
  ASSERT_GT(k5.word_bits, 0);
  EXPECT_LE(k5.path_error_fixed_blu, 1.0);
  // The next h up the grid misses 0.5 BLU, and one bit less misses 1 BLU.
  EXPECT_GT(run_quarter(Method::kK5, r, k5.h * std::pow(2.0, 0.25), Starter::kK7, Arithmetic::double_precision())
                .max_path_error,
            0.5);
  EXPECT_GT(run_quarter(Method::kK5, r, k5.h, Starter::kK7, Arithmetic::fixed(k5.word_bits - 1)).max_path_error, 1.0);
  EXPECT_FALSE(sampled_for_one_blu(Method::kK6, r, Starter::kK7).reached);
}

TEST(Study, SmallSweepFitsTheOrders) {
  StudyConfig cfg;
  cfg.radii_mm = {1.0, 10.0};
  cfg.hs = {1e-3, 1e-2};
  cfg.turns = 2;
  const Study s = run_study(cfg);
  EXPECT_EQ(s.rows.size(), 8u * 2 * 2);
  for (const MethodSummary& m : s.summaries) {
    const double expected = m.method == Method::kK1 || m.method == Method::kK4 ? 1
                            : m.method == Method::kK5                          ? 2
                            : m.method == Method::kK2 || m.method == Method::kK7 ? 3
                            : m.method == Method::kK3                          ? 4
                                                                               : 0;
    if (m.method == Method::kL1) {
      EXPECT_EQ(m.roundoff_rows, m.rows);  // on the line up to round-off
      continue;
    }
    ASSERT_TRUE(m.error.valid) << method_name(m.method);
    EXPECT_NEAR(m.error.order, expected, 0.05) << method_name(m.method);
  }
  StudyConfig bad = cfg;
  bad.turns = 1;
  EXPECT_THROW(run_study(bad), std::invalid_argument);
}

}  // namespace
}  // namespace ncinterp::sampled
