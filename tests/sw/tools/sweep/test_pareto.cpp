// The Pareto front and the board recommendations on made-up results: domination over
// area, error and tape length; points that failed or lack a value stay out; each board's
// pick is the front's smallest error that fits, by the board's own placement, and whose
// clock the placement's Fmax reaches.
#include <gtest/gtest.h>

#include "pareto.h"

namespace ncinterp::sweep {
namespace {

PointResult point(double cells, double error_mm, uint64_t frames, double hx1k_cells = 0) {
  PointResult r;
  r.point = {{"IncWidth", cells}};
  InputResult in;
  in.input = "x.json";
  in.total_error_max_mm = error_mm;
  in.frames = frames;
  r.row.inputs = {in};
  r.row.synth.ice40_logic_cells = Measured::of(cells);
  r.row.synth.fmax_mhz = cells <= 7680 ? Measured::of(30) : Measured::absent("too big for the HX8K");
  r.row.synth.small_logic_cells = Measured::of(hx1k_cells ? hx1k_cells : cells);
  r.row.synth.small_fmax_mhz = (hx1k_cells ? hx1k_cells : cells) <= 1280 ? Measured::of(30) : Measured::absent("too big");
  return r;
}

TEST(Pareto, KeepsThePointsNoOtherBeatsOnEveryObjective) {
  std::vector<PointResult> rs = {point(1000, 0.010, 5000),  // front: smallest area
                                 point(2000, 0.010, 5000),  // beaten by 0
                                 point(3000, 0.005, 9000),  // front: smallest error
                                 point(4000, 0.010, 1000),  // front: shortest tape
                                 point(4000, 0.010, 1000),  // equal to 3: neither beats the other
                                 point(500, 0.001, 100)};   // would beat all, but fails its check
  rs[5].row.inputs[0].violations = 1;
  const ParetoFront f = pareto_front(rs);
  EXPECT_EQ(f.objectives, (std::vector<std::string>{"ice40_logic_cells", "total_error_max_mm", "tape_frames"}));
  EXPECT_EQ(f.members, (std::vector<size_t>{0, 2, 3, 4}));
  EXPECT_EQ(f.eligible, 5u);
}

TEST(Pareto, WithoutAreaTheFrontIsOverErrorAndTape) {
  std::vector<PointResult> rs = {point(1000, 0.010, 5000), point(2000, 0.010, 4000)};
  for (PointResult& r : rs) r.row.synth.ice40_logic_cells = Measured::absent("not run (--no-synth)");
  const ParetoFront f = pareto_front(rs);
  EXPECT_EQ(f.objectives, (std::vector<std::string>{"total_error_max_mm", "tape_frames"}));
  EXPECT_EQ(f.members, (std::vector<size_t>{1}));
  for (const Recommendation& r : recommend(rs, f, 1e6)) {
    EXPECT_FALSE(r.point);
    EXPECT_EQ(r.why, "no area measured (synthesis not run)");
  }
}

TEST(Pareto, EachBoardGetsTheSmallestErrorThatFitsIt) {
  const std::vector<PointResult> rs = {point(1200, 0.009, 9000),   // fits everything
                                       point(5000, 0.006, 3000),   // UP5K and HX8K
                                       point(7000, 0.004, 2000),   // HX8K only
                                       point(9000, 0.001, 1000)};  // fits no board
  const ParetoFront f = pareto_front(rs);
  EXPECT_EQ(f.members.size(), 4u);
  const std::vector<Recommendation> recs = recommend(rs, f, 1e6);
  ASSERT_EQ(recs.size(), 3u);
  EXPECT_EQ(recs[0].board.name, "HX1K");
  EXPECT_EQ(recs[0].point, std::optional<size_t>(0));
  EXPECT_EQ(recs[1].board.name, "UP5K");
  EXPECT_EQ(recs[1].point, std::optional<size_t>(1));
  EXPECT_EQ(recs[2].board.name, "HX8K");
  EXPECT_EQ(recs[2].point, std::optional<size_t>(2));

  // The HX1K is judged by its own placement: a point the HX1K cannot hold is not its pick.
  const std::vector<PointResult> big = {point(1200, 0.009, 9000, 1400)};
  const std::vector<Recommendation> r2 = recommend(big, pareto_front(big), 1e6);
  EXPECT_FALSE(r2[0].point);
  EXPECT_EQ(r2[0].why, "no point of the front fits (1280 logic cells, Fmax at least its clock)");
  EXPECT_EQ(r2[1].point, std::optional<size_t>(0));
}

// A board must also run the point at its clock: the placement's Fmax (30 MHz here) at
// least the point's clock_hz, else the next point of the front that does.
TEST(Pareto, ABoardIsNoPickForAPointWhoseClockItCannotReach) {
  std::vector<PointResult> rs = {point(1000, 0.009, 9000), point(1100, 0.002, 9000)};
  rs[0].point[kClock] = 12e6;
  rs[1].point[kClock] = 48e6;  // the smaller error, but above the 30 MHz Fmax
  const ParetoFront f = pareto_front(rs);
  ASSERT_EQ(f.members.size(), 2u);
  for (const Recommendation& r : recommend(rs, f, 1e6)) EXPECT_EQ(r.point, std::optional<size_t>(0)) << r.board.name;
  rs[1].point.erase(kClock);  // the default clock, 1 MHz here, and 40 MHz: the pick again / none
  EXPECT_EQ(recommend(rs, pareto_front(rs), 1e6)[0].point, std::optional<size_t>(1));
  EXPECT_EQ(recommend(rs, pareto_front(rs), 40e6)[0].point, std::optional<size_t>(0));
}

// Total errors closer than 0.1 um are a tie (no tape can express the difference): the
// shorter tape wins; a tie left after tape and area goes to the smaller feed error (what
// a faster clock buys), not to grid order.
TEST(Pareto, ErrorsBelowATenthOfAMicrometreTieAndTheFeedErrorBreaksWhatIsLeft) {
  const std::vector<PointResult> rs = {point(1000, 0.010000, 9000), point(2000, 0.010050, 5000)};
  const ParetoFront f = pareto_front(rs);
  ASSERT_EQ(f.members.size(), 2u);
  EXPECT_EQ(recommend(rs, f, 1e6)[2].point, std::optional<size_t>(1));  // HX8K: the shorter tape

  std::vector<PointResult> clocks = {point(1000, 0.01, 9000), point(1000, 0.01, 9000)};
  clocks[0].row.inputs[0].feed_error_worst = -1e-4;
  clocks[1].row.inputs[0].feed_error_worst = 1e-6;
  EXPECT_EQ(recommend(clocks, pareto_front(clocks), 1e6)[2].point, std::optional<size_t>(1));
}

}  // namespace
}  // namespace ncinterp::sweep
