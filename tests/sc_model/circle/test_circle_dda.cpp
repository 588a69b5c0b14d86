// The golden circle DDA on its own: every quadrant arc ends exactly at its programmed end
// with |dx| and |dy| pulses in the right directions, within the radial error bound of
// docs/circle-dda.md (measured by bench/circle), in fewer than 2^(k+1) iterations (the
// iteration counter's width); a full circle of four quadrant blocks closes and ten turns
// repeat the first one exactly. Exhaustive over every good arc of a 5-bit machine.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>

#include "arc_geometry.h"
#include "dda_circle.h"
#include "arc_cases.h"

namespace ncinterp {
namespace {

using circle_study::ArcRunStats;
using circle_study::full_quadrant;
using circle_study::QuadrantArc;
using circle_study::run_arc;

// The stated bounds (docs/circle-dda.md 3.2), measured by bench/circle: every pulse
// position is within kDdaBound of the circle through the start plus the end's own distance
// from that circle (<= 1 BLU by the radius rule), and never more than kPathBound off it.
constexpr double kDdaBound = 0.88;
constexpr double kPathBound = 1.0;

::testing::AssertionResult arc_plays_exactly(const QuadrantArc& a, unsigned w) {
  const ArcRunStats s = run_arc(a, w, uint64_t{1} << (w + 2));
  const int64_t dx = a.x1 - a.x0, dy = a.y1 - a.y0;
  if (!s.finished)
    return ::testing::AssertionFailure() << a.describe() << ": not finished after "
                                         << s.iterations << " iterations";
  if (s.x != a.x1 || s.y != a.y1)
    return ::testing::AssertionFailure() << a.describe() << ": ends at (" << s.x << ", " << s.y
                                         << ")";
  const uint64_t want[2][2] = {{uint64_t(dx < 0 ? -dx : 0), uint64_t(dx > 0 ? dx : 0)},
                               {uint64_t(dy < 0 ? -dy : 0), uint64_t(dy > 0 ? dy : 0)}};
  for (int ax = 0; ax < 2; ++ax)
    for (int plus = 0; plus < 2; ++plus)
      if (s.pulses[ax][plus] != want[ax][plus])
        return ::testing::AssertionFailure()
               << a.describe() << ": " << s.pulses[ax][plus] << (plus ? " plus" : " minus")
               << " pulses on " << "XY"[ax] << ", programmed " << want[ax][plus];
  if (s.iterations >= (uint64_t{2} << s.k))
    return ::testing::AssertionFailure() << a.describe() << ": " << s.iterations
                                         << " iterations >= 2^(k+1), k = " << s.k;
  const double bound =
      std::min(kPathBound + 1e-12, kDdaBound + std::fabs(a.end_radius() - a.start_radius()));
  if (s.max_radial_error > bound)
    return ::testing::AssertionFailure()
           << a.describe() << ": pulse at (" << s.worst_x << ", " << s.worst_y << ") is "
           << s.max_radial_error << " BLU off the circle (bound " << bound << ")";
  const double spiral_bound = kDdaBound + std::fabs(a.end_radius() - a.start_radius());
  if (s.max_spiral_error > spiral_bound)
    return ::testing::AssertionFailure() << a.describe() << ": " << s.max_spiral_error
                                         << " BLU off the arc of linearly changing radius (bound "
                                         << spiral_bound << ")";
  return ::testing::AssertionSuccess();
}

TEST(CircleDda, EveryFullQuadrantOfRadius1To3000) {
  for (int64_t r = 1; r <= 3000; ++r)
    for (int q = 0; q < 4; ++q)
      for (bool ccw : {false, true}) ASSERT_TRUE(arc_plays_exactly(full_quadrant(r, q, ccw), 16));
}

TEST(CircleDda, FullQuadrantsUpToTheLargestRadius) {
  for (int64_t r : {4095, 4096, 32767, 32768, 50000, 65534, 65535})
    for (int q = 0; q < 4; ++q)
      for (bool ccw : {false, true}) ASSERT_TRUE(arc_plays_exactly(full_quadrant(r, q, ccw), 16));
}

TEST(CircleDda, RandomArcsAtW16) {
  std::mt19937_64 rng(1);
  for (int t = 0; t < 600; ++t) ASSERT_TRUE(arc_plays_exactly(circle_study::random_arc(rng, 65535), 16));
}

TEST(CircleDda, RandomArcsAtOtherWidths) {
  std::mt19937_64 rng(2);
  for (unsigned w : {2u, 3u, 8u, 20u})
    for (int t = 0; t < 200; ++t)
      ASSERT_TRUE(arc_plays_exactly(circle_study::random_arc(rng, (int64_t{1} << w) - 1), w)) << "W " << w;
}

// Every good arc of a 5-bit machine (start and end magnitudes <= 31, both directions).
TEST(CircleDda, EveryGoodArcOfA5BitMachine) {
  const int64_t lim = 31;
  uint64_t arcs = 0;
  for (int64_t x0 = -lim; x0 <= lim; ++x0)
    for (int64_t y0 = -lim; y0 <= lim; ++y0)
      for (int64_t x1 = -lim; x1 <= lim; ++x1)
        for (int64_t y1 = -lim; y1 <= lim; ++y1) {
          const double d = std::hypot(double(x1), double(y1)) - std::hypot(double(x0), double(y0));
          if (std::fabs(d) > 1.5) continue;  // cheap prefilter; check_arc decides
          for (bool ccw : {false, true}) {
            QuadrantArc a;
            a.x0 = x0;
            a.y0 = y0;
            a.x1 = x1;
            a.y1 = y1;
            a.ccw = ccw;
            if (check_arc(a.words(), 5) != TapeError::kNone) continue;
            ++arcs;
            ASSERT_TRUE(arc_plays_exactly(a, 5));
          }
        }
  EXPECT_GT(arcs, 50000u);
}

// A circle of radius 50 mm (50000 BLU) as four quadrant blocks, ten turns: each block
// starts where the previous one really ended; the tool returns exactly to the start and
// every turn is the same pulse path as the first (no drift).
TEST(CircleDda, TenTurnsOfFourQuadrantBlocksCloseAndDoNotDrift) {
  const int64_t r = 50000;
  int64_t x = r, y = 0;
  double first_turn_error = -1;
  uint64_t first_turn_iterations = 0;
  for (int turn = 0; turn < 10; ++turn) {
    double turn_error = 0;
    uint64_t turn_iterations = 0;
    for (int q = 0; q < 4; ++q) {
      QuadrantArc a = full_quadrant(r, q, true);
      a.x0 = x;
      a.y0 = y;
      ASSERT_TRUE(arc_plays_exactly(a, 16));
      const ArcRunStats s = run_arc(a, 16, 1u << 20);
      x = s.x;
      y = s.y;
      turn_error = std::max(turn_error, s.max_radial_error);
      turn_iterations += s.iterations;
    }
    ASSERT_EQ(x, r);
    ASSERT_EQ(y, 0);
    if (turn == 0) {
      first_turn_error = turn_error;
      first_turn_iterations = turn_iterations;
      EXPECT_LE(first_turn_error, kDdaBound);
    }
    EXPECT_EQ(turn_error, first_turn_error) << "turn " << turn + 1;
    EXPECT_EQ(turn_iterations, first_turn_iterations) << "turn " << turn + 1;
  }
}

TEST(CircleDda, ImmediateUpdateAlternatesTheOrder) {
  // Radius 1, Q1 ccw, k = 1, integrators start at 1. Iteration 1, X first: X adds |y| = 0
  // (no carry), then Y adds |x| = 1 (carry: Y steps, its last pulse). Iteration 2, Y first:
  // Y has no pulse left; X adds |y| = 1 with bit k-1 forced (Y is done): carry, X steps.
  CircleDda d;
  d.load(arc_geometry(full_quadrant(1, 0, true).words(), 16), false, true);
  EXPECT_FALSE(d.y_first());
  CircleDda::Steps s = d.iterate();
  EXPECT_FALSE(s.x);
  EXPECT_TRUE(s.y);
  EXPECT_TRUE(d.y_first());
  s = d.iterate();
  EXPECT_TRUE(s.x);
  EXPECT_FALSE(s.y);
  EXPECT_TRUE(d.done());
}

}  // namespace
}  // namespace ncinterp
