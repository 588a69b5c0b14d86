// The programmed path read from a tape: blocks laid end to end, distances to lines and to
// G02/G03 arcs (inside the sweep: radial; outside: the nearer end).
#include <gtest/gtest.h>

#include <cmath>

#include "programmed_path.h"

namespace ncinterp::checker {
namespace {

tape::Block arc(tape::Motion m, int64_t dx, int64_t dy, int64_t i, int64_t j) {
  tape::Block b;
  b.motion = m;
  b.dx = dx, b.dy = dy, b.i = i, b.j = j;
  b.feed = 1000;
  return b;
}

TEST(ProgrammedPath, BlocksAreLaidEndToEndFromTheOrigin) {
  tape::Program p;
  p.blocks = {arc(tape::Motion::kLine, 100, 0, 0, 0), arc(tape::Motion::kArcCcw, -100, 100, -100, 0),
              arc(tape::Motion::kLine, 0, -100, 0, 0)};
  const auto blocks = lay_out(p);
  ASSERT_EQ(blocks.size(), 3u);
  EXPECT_EQ(blocks[1].start, (GridPoint{100, 0}));
  EXPECT_EQ(blocks[1].end, (GridPoint{0, 100}));
  EXPECT_NEAR(blocks[1].centre.x, 0.0, 0);
  EXPECT_NEAR(blocks[1].sweep(), M_PI / 2, 1e-12);
  EXPECT_NEAR(blocks[1].length(), 50 * M_PI, 1e-9);
  EXPECT_EQ(blocks[2].end, (GridPoint{0, 0}));
}

TEST(ProgrammedPath, LineDistanceIsToTheSegment) {
  tape::Program p;
  p.blocks = {arc(tape::Motion::kLine, 300, 400, 0, 0)};
  const auto b = lay_out(p)[0];
  EXPECT_NEAR(distance_to_block(b, {400, -300}), 500.0, 1e-9);        // on the normal at the start
  EXPECT_NEAR(distance_to_block(b, {300 + 4, 400 - 3}), 5.0, 1e-9);    // on the normal at the end
  EXPECT_NEAR(distance_to_block(b, {150 - 40, 200 + 30}), 50.0, 1e-9); // on the normal at the middle
  EXPECT_NEAR(distance_to_block(b, {-30, -40}), 50.0, 1e-9);          // before the start
}

TEST(ProgrammedPath, CounterClockwiseQuarter) {
  // A quarter from the tape start (0, 0) about the centre (-1000, 0) to (-1000, 1000).
  tape::Program p;
  p.blocks = {arc(tape::Motion::kArcCcw, -1000, 1000, -1000, 0)};
  auto b = lay_out(p)[0];
  double along = -1;
  EXPECT_NEAR(distance_to_block(b, {-1000 + 1100 * std::cos(0.3), 1100 * std::sin(0.3)}, &along), 100.0, 1e-9);
  EXPECT_NEAR(along, 0.3 / (M_PI / 2), 1e-12);
  // Below the start, outside the sweep: distance to the start point.
  EXPECT_NEAR(distance_to_block(b, {0, -50}), 50.0, 1e-9);
}

TEST(ProgrammedPath, ClockwiseQuarterAndRadiusDrift) {
  tape::Program p;  // from (0,0) clockwise about (0,-1000) to (1000,-999): end radius 1000.5
  p.blocks = {arc(tape::Motion::kArcCw, 1000, -999, 0, -1000)};
  auto b = lay_out(p)[0];
  EXPECT_LT(b.sweep(), 0.0);
  EXPECT_NEAR(b.sweep(), -std::atan2(1000.0, 1.0), 1e-12);
  // Half way: the radius is interpolated between 1000 and |(1000, 1)| linearly in angle.
  const double r1 = std::hypot(1000.0, 1.0);
  const double half = 0.5 * b.sweep(), th = M_PI / 2 + half;
  const Vec2 q{1000 * std::cos(th), -1000 + 1000 * std::sin(th)};
  EXPECT_NEAR(distance_to_block(b, q), 0.5 * (r1 - 1000), 1e-9);
  // A counter-clockwise block over the same points goes the long way round (3/4 circle).
  p.blocks = {arc(tape::Motion::kArcCcw, 1000, -999, 0, -1000)};
  EXPECT_NEAR(lay_out(p)[0].sweep(), 2 * M_PI - std::atan2(1000.0, 1.0), 1e-12);
}

TEST(ProgrammedPath, FullCircle) {
  tape::Program p;
  p.blocks = {arc(tape::Motion::kArcCw, 0, 0, 500, 0)};
  const auto b = lay_out(p)[0];
  EXPECT_NEAR(b.sweep(), -2 * M_PI, 0);
  EXPECT_NEAR(distance_to_block(b, {500, 450}), 50.0, 1e-9);
}

}  // namespace
}  // namespace ncinterp::checker
