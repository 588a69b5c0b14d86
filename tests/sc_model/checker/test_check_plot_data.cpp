// The plot series keep what matters: the worst point is inside its zoom with its foot, the
// staircase inside the zoom is every pulse there (unit steps), no error peak is lost by the
// binning along the path; the feed profile counts every pulse and shows the ramps.
#include <gtest/gtest.h>

#include <cmath>

#include "check_plot_data.h"
#include "checker_test_support.h"

namespace ncinterp::checker {
namespace {

// A 48-gon inscribed in the circle of radius 20 + cutter_mm about the origin, checked
// against the circle of radius 20 (the part; with a cutter, outside it: on the right of the
// counter-clockwise travel).
CheckOutcome inscribed_polygon_check(double cutter_mm = 0.0, double accel_mm_s2 = 0.0) {
  firststage::Contour circle;
  circle.origin = {20.0, 0.0};
  circle.segments.push_back(firststage::Segment::arc({0, 0}, 20.0, 0.0, 2 * M_PI));
  circle.element_names = {"circle"};
  tape::Program p;
  const double r = 20000 + 1000 * cutter_mm;
  int64_t px = std::llround(r), py = 0;
  for (int k = 1; k <= 48; ++k) {
    const double a = 2 * M_PI * k / 48;
    const int64_t x = std::llround(r * std::cos(a)), y = std::llround(r * std::sin(a));
    tape::Block b;
    b.n = static_cast<uint32_t>(k);
    b.dx = x - px, b.dy = y - py, b.feed = 4'000'000;
    p.blocks.push_back(b);
    px = x, py = y;
  }
  CheckSetup setup;
  setup.reader_cps = 1e6;
  setup.tol_mm = 0.1;
  setup.accel_mm_s2 = accel_mm_s2;
  if (cutter_mm > 0) {
    setup.cutter_radius_mm = cutter_mm;
    setup.cutter_left = false;
    setup.start_mm = firststage::Vec2{20.0 + cutter_mm, 0.0};
  }
  return run_check(test::frames_of(p), &circle, setup);
}

TEST(CheckPlotData, WorstPointZoomAndBins) {
  const CheckOutcome out = inscribed_polygon_check();
  ASSERT_TRUE(out.passed());
  const CheckPlotData d = check_plot_data(out, 0.1, 1e6, 500);
  ASSERT_TRUE(d.has_worst);
  EXPECT_TRUE(d.zoom.contains(d.worst));
  EXPECT_NEAR(std::hypot(d.worst.x - d.worst_foot.x, d.worst.y - d.worst_foot.y), d.worst_error_mm, 1e-6);
  EXPECT_NEAR(std::hypot(d.worst_foot.x, d.worst_foot.y), 20.0, 1e-6);  // the foot is on the circle
  // Overview holds the whole circle.
  EXPECT_LE(d.overview.x0, -20.0);
  EXPECT_GE(d.overview.x1, 20.0);
  // The staircase in the zoom: consecutive pulses one step apart per axis.
  size_t pulses = 0;
  for (const Polyline& run : d.zoom_pulses) {
    for (size_t i = 1; i < run.size(); ++i) {
      EXPECT_LE(std::fabs(run[i].x - run[i - 1].x), 0.001 + 1e-9);
      EXPECT_LE(std::fabs(run[i].y - run[i - 1].y), 0.001 + 1e-9);
    }
    pulses += run.size();
  }
  EXPECT_GT(pulses, 50u);
  EXPECT_FALSE(d.zoom_contour.empty());
  EXPECT_FALSE(d.zoom_programmed.empty());
  // Binning keeps the peak.
  double peak = 0.0;
  for (const ErrorBin& b : d.error_bins) peak = std::max(peak, b.total_max);
  EXPECT_NEAR(peak, d.worst_error_mm, 1e-6);
  // The staircase is longer than the circle, and at most sqrt(2) times its 4-connected
  // length (4/pi the circle).
  EXPECT_GT(d.path_length_mm, 2 * M_PI * 20.0);
  EXPECT_LT(d.path_length_mm, 8 * 20.0 * std::sqrt(2.0));
}

// With a cutter the zoom shows the cutter-centre path (the contour moved R outwards) and
// the worst point's foot lies on it, R from the part.
TEST(CheckPlotData, CutterZoomShowsTheCutterCentrePath) {
  const CheckOutcome out = inscribed_polygon_check(2.0);
  ASSERT_TRUE(out.passed());
  const CheckPlotData d = check_plot_data(out, 0.1, 1e6, 500);
  ASSERT_TRUE(d.has_worst);
  EXPECT_TRUE(d.cutter);
  EXPECT_NEAR(std::hypot(d.worst_foot.x, d.worst_foot.y), 22.0, 1e-6);
  EXPECT_NEAR(std::hypot(d.worst.x - d.worst_foot.x, d.worst.y - d.worst_foot.y), d.worst_error_mm, 1e-6);
  ASSERT_FALSE(d.zoom_contour.empty());
  for (const Polyline& run : d.zoom_contour)
    for (const PlotPoint& q : run) EXPECT_NEAR(std::hypot(q.x, q.y), 22.0, 1e-9);
}

// The profile's bins hold every step (speed x bin time = BLU moved). With the ramp every
// block starts from rest, so the profile starts low, the part takes longer (a lower mean
// speed: its 48 chords over the run's time) and no bin is faster than unramped.
TEST(CheckPlotData, FeedProfileCountsEveryStepAndShowsTheRamp) {
  auto profile = [](const CheckOutcome& out) {
    const CheckPlotData d = check_plot_data(out, 0.1, 1e6, 500, 200);
    EXPECT_EQ(d.speed_bins.size(), 200u);
    double steps = 0.0, fastest = 0.0;
    const double bin_s = d.speed_bins[1].t_s - d.speed_bins[0].t_s;
    for (const SpeedBin& b : d.speed_bins) {
      steps += (b.x_mm_min + b.y_mm_min) * bin_s / 60.0 / 0.001;
      fastest = std::max(fastest, std::hypot(b.x_mm_min, b.y_mm_min));
    }
    uint64_t moved = 0;
    GridPoint last{0, 0};
    for (const PulseSample& p : out.checker->pulses()) {
      moved += std::llabs(p.position.x - last.x) + std::llabs(p.position.y - last.y);
      last = p.position;
    }
    EXPECT_NEAR(steps, static_cast<double>(moved), 1e-6 * moved);
    const double mean = 48 * 2 * 20.0 * std::sin(M_PI / 48) / (out.checker->pulses().back().cycle / 1e6) * 60;
    return std::tuple{d.speed_bins.front(), fastest, mean};
  };
  const CheckOutcome plain = inscribed_polygon_check();
  ASSERT_TRUE(plain.passed());
  const auto [plain_first, plain_fastest, plain_mean] = profile(plain);
  EXPECT_GT(plain_fastest, plain_mean);
  const CheckOutcome ramped = inscribed_polygon_check(0.0, 500.0);
  ASSERT_TRUE(ramped.passed());
  const auto [ramped_first, ramped_fastest, ramped_mean] = profile(ramped);
  EXPECT_LT(ramped_mean, plain_mean);
  EXPECT_LE(ramped_fastest, plain_fastest * 1.05);
  EXPECT_LT(std::hypot(ramped_first.x_mm_min, ramped_first.y_mm_min),
            0.5 * std::hypot(plain_first.x_mm_min, plain_first.y_mm_min));
}

}  // namespace
}  // namespace ncinterp::checker
