// The feed plan (sc_model/checker/feed_plan.h) on tapes whose times follow from the
// trapezoid by hand: exact stop is continuous mode where every corner is a reversal;
// collinear short blocks flow in continuous mode as one long block once the whole tape
// is read, and as fast as a stop within the blocks read allows with less look-ahead;
// corners take the junction-deviation speed; M00, M05, M03 and still blocks stop the
// axes. (That exact stop is what the machine plays is checked on played runs:
// RampedRegression.KeepsThePulsesOnBothArchs.)
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "feed_plan.h"
#include "tape.h"

namespace ncinterp::checker {
namespace {

constexpr double kClock = 12e6, kAccel = 500;

FeedPlan plan(const std::string& body, std::vector<unsigned> lookaheads = {1, 2, 4, 0}) {
  const tape::Program p = tape::parse_frames(tape::add_parity("%\nG17 G21 G91 G93\n" + body + "M02\n%\n"), {});
  FeedPlanOptions o;
  o.accel_mm_s2 = kAccel;
  o.lookaheads = std::move(lookaheads);
  return plan_feed(p, interp_config(kClock), kClock, o);
}

// `count` blocks of `step` BLU along X at 20 mm/s (inverse time F = 1200 / step mm).
std::string chain(int count, int step, const char* extra = "") {
  std::string s;
  char line[96];
  for (int n = 1; n <= count; ++n) {
    std::snprintf(line, sizeof line, "N%d G01 X%.3f F%.3f%s\n", n, step / 1000.0, 1200.0 / (step / 1000.0),
                  n == count / 2 ? extra : "");
    s += line;
  }
  return s;
}

// The ramp's acceleration along a line of `blu` BLU along X: the limit times L / N.
double line_accel(int blu) { return kAccel * blu / std::exp2(std::ceil(std::log2(blu + 1.0))); }

TEST(FeedPlan, AReversalAtEveryCornerIsExactStop) {
  const FeedPlan p = plan("N1 G01 X10.000 F120.000\nN2 G01 X-10.000 F120.000\nN3 G01 X10.000 F120.000\n");
  ASSERT_EQ(p.continuous.size(), 4u);
  for (const ContinuousPlan& c : p.continuous) EXPECT_NEAR(c.seconds, p.exact_stop_s, 1e-9 * p.exact_stop_s);
  // Each block: 10 mm at 20 mm/s plus v / a of its ramp.
  EXPECT_NEAR(p.exact_stop_s, 3 * (0.5 + 20 / line_accel(10000)), 1e-6);
  EXPECT_NEAR(p.programmed_s, 1.5, 1e-6);
}

TEST(FeedPlan, CollinearShortBlocksFlowAsFarAsTheLookAheadLetsThemStop) {
  // 100 blocks of 0.1 mm: a stop from 20 mm/s takes 20^2 / (2 a) = 0.51 mm, five blocks.
  const FeedPlan p = plan(chain(100, 100));
  const double a = line_accel(100);
  ASSERT_EQ(p.continuous.size(), 4u);
  // The whole tape read: one 10 mm trapezoid.
  EXPECT_NEAR(p.continuous[3].seconds, 10 / 20.0 + 20 / a, 1e-3);
  // One block read: every block ends at w = sqrt(2 a 0.1 mm), from which a stop within the
  // next block is possible, and peaks at sqrt(w^2 + a 0.1 mm) halfway (the ends aside).
  const double w = std::sqrt(2 * a * 0.1), peak = std::sqrt(w * w + a * 0.1);
  EXPECT_NEAR(p.continuous[0].seconds, 100 * 2 * (peak - w) / a, 0.03 * p.continuous[0].seconds);
  EXPECT_GT(p.continuous[0].seconds, p.continuous[1].seconds);
  EXPECT_GT(p.continuous[1].seconds, p.continuous[2].seconds);
  EXPECT_GT(p.continuous[2].seconds, p.continuous[3].seconds);
  EXPECT_GT(p.exact_stop_s, 2 * p.continuous[0].seconds);
}

TEST(FeedPlan, ARightAngleIsTakenAtTheJunctionDeviationSpeed) {
  // 20 mm/s into and out of the corner; junction v^2 = A d sin(45) / (1 - sin(45)).
  const FeedPlan p = plan("N1 G01 X10.000 F120.000\nN2 G01 Y10.000 F120.000\n", {0});
  const double a = line_accel(10000), s = std::sqrt(0.5);
  const double vj = std::sqrt(kAccel * 0.01 * s / (1 - s));
  // Each block: 10 mm at 20 mm/s, plus what ramping between rest and 20 mm/s and between
  // vj and 20 mm/s loses: (20 - v)^2 / (2 a 20) each.
  const double lost = (20.0 * 20.0 + (20 - vj) * (20 - vj)) / (2 * a * 20);
  EXPECT_NEAR(p.continuous[0].seconds, 2 * (0.5 + lost), 1e-6);
  EXPECT_LT(p.continuous[0].seconds, p.exact_stop_s);
}

TEST(FeedPlan, StopsAndTheToolRestTheAxes) {
  const FeedPlan flowing = plan(chain(20, 1000), {0});
  for (const char* word : {" M00", " M05", " M03"}) {
    SCOPED_TRACE(word);
    const FeedPlan stopping = plan(chain(20, 1000, word), {0});
    // One more stop and start: v / a more.
    EXPECT_NEAR(stopping.continuous[0].seconds - flowing.continuous[0].seconds, 20 / line_accel(1000), 1e-6);
  }
  const FeedPlan still = plan("N1 G01 X10.000 F120.000\nN2 M00\nN3 G01 X10.000 F120.000\n", {0});
  const FeedPlan joined = plan("N1 G01 X10.000 F120.000\nN3 G01 X10.000 F120.000\n", {0});
  EXPECT_GT(still.continuous[0].seconds, joined.continuous[0].seconds + 20 / line_accel(10000) - 1e-3);
}

}  // namespace
}  // namespace ncinterp::checker
