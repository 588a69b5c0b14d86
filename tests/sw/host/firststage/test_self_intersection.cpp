// Self-crossing paths: a figure eight is found where its strokes cross; a closed square,
// a path that goes back over itself, and pieces touching at a point are not crossings;
// run_first_stage turns a crossing into one warning naming the elements.
#include <gtest/gtest.h>

#include "firststage.h"
#include "measure/self_intersection.h"

namespace ncinterp::firststage {
namespace {

Move line_to(int64_t x, int64_t y) {
  Move m;
  m.to = {x, y};
  return m;
}

TEST(SelfCrossing, FigureEightCrossesAtItsMiddle) {
  // (0,0) -> (10,10) -> (10,0) -> (0,10) -> (0,0): the diagonals cross at (5,5).
  const std::vector<Move> moves = {line_to(10, 10), line_to(10, 0), line_to(0, 10), line_to(0, 0)};
  const auto x = find_self_crossing({0, 0}, moves);
  ASSERT_TRUE(x.has_value());
  EXPECT_NEAR(x->at.x, 5.0, 1e-9);
  EXPECT_NEAR(x->at.y, 5.0, 1e-9);
  EXPECT_EQ(x->move_a, 0);
  EXPECT_EQ(x->move_b, 2);
}

TEST(SelfCrossing, ClosedSquareRetraceAndTouchAreNotCrossings) {
  EXPECT_FALSE(find_self_crossing({0, 0}, {line_to(10, 0), line_to(10, 10), line_to(0, 10), line_to(0, 0)}));
  EXPECT_FALSE(find_self_crossing({0, 0}, {line_to(10, 0), line_to(2, 0), line_to(12, 0)}));
  // (10,0) -> (5,5) -> (5,0): the third piece ends on the first one, a touch.
  EXPECT_FALSE(find_self_crossing({0, 0}, {line_to(10, 0), line_to(5, 5), line_to(5, 0)}));
}

TEST(SelfCrossing, RapidsAreNotPartOfThePath) {
  std::vector<Move> moves = {line_to(10, 10), line_to(10, 0), line_to(0, 10)};
  moves[2].rapid = true;
  EXPECT_FALSE(find_self_crossing({0, 0}, moves));
}

TEST(SelfCrossing, ArcBlockCrossingALine) {
  // A ccw half circle about (0,0) radius 10 from (10,0) to (-10,0), then a line down through it.
  Move arc;
  arc.kind = MoveKind::kArcCcw;
  arc.to = {-10, 0};
  arc.centre = {0, 0};
  const std::vector<Move> moves = {arc, line_to(0, 20), line_to(0, 5)};
  const auto x = find_self_crossing({10, 0}, moves);
  ASSERT_TRUE(x.has_value());
  EXPECT_EQ(x->move_a, 0);
  EXPECT_EQ(x->move_b, 1);
}

TEST(SelfCrossing, FirstStageWarnsNamingTheElements) {
  const Contour c = contour_from_segments(
      "eight.json", {0, 0},
      {Segment::line({0, 0}, {10, 10}), Segment::line({10, 10}, {10, 0}), Segment::line({10, 0}, {0, 10}),
       Segment::line({0, 10}, {0, 0})});
  const FirstStageResult r = run_first_stage(c, FirstStageOptions{});
  ASSERT_EQ(r.warnings.size(), 1u);
  EXPECT_EQ(r.warnings[0],
            "eight.json: warning: the contour crosses itself at (5.000, 5.000) mm (segment 1 and "
            "segment 3): the tape cuts it as drawn");
  const Contour square = contour_from_segments(
      "square.json", {0, 0},
      {Segment::line({0, 0}, {10, 0}), Segment::line({10, 0}, {10, 10}), Segment::line({10, 10}, {0, 10}),
       Segment::line({0, 10}, {0, 0})});
  FirstStageOptions o;
  o.cutter_radius_mm = 1.0;
  EXPECT_TRUE(run_first_stage(square, o).warnings.empty());
}

}  // namespace
}  // namespace ncinterp::firststage
