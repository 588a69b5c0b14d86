// Arc block rules (docs/circle-dda.md section 2): the exact radius rule against real
// arithmetic, the quadrant rule on every quadrant and on the axes, the error order, the
// geometry the DDA is loaded with, and the decoder's arc preparation (checks + dry run):
// its result, its S = F * N and the clock it finishes.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>

#include "arc_geometry.h"
#include "arc_prepare.h"
#include "dda_circle.h"
#include "arc_cases.h"

namespace ncinterp {
namespace {

using circle_study::full_quadrant;
using circle_study::QuadrantArc;

QuadrantArc arc(int64_t x0, int64_t y0, int64_t x1, int64_t y1, bool ccw) {
  QuadrantArc a;
  a.x0 = x0;
  a.y0 = y0;
  a.x1 = x1;
  a.y1 = y1;
  a.ccw = ccw;
  return a;
}

TEST(ArcCheck, RadiusRuleEqualsRealArithmeticAwayFromTies) {
  std::mt19937_64 rng(11);
  int accepted = 0, rejected = 0;
  for (int t = 0; t < 200000; ++t) {
    const uint64_t x0 = rng() % 65536, y0 = rng() % 65536;
    if (x0 == 0 && y0 == 0) continue;
    const double r0 = std::hypot(double(x0), double(y0));
    // An end near the circle: radius r0 + offset in [-2, 2], random angle.
    const double off = (double(rng() % 4001) - 2000.0) / 1000.0;
    const double ang = double(rng() % 100000) / 100000.0 * M_PI / 2;
    const int64_t x1 = std::llround((r0 + off) * std::cos(ang));
    const int64_t y1 = std::llround((r0 + off) * std::sin(ang));
    if (x1 < 0 || y1 < 0) continue;
    const double diff = std::fabs(std::hypot(double(x1), double(y1)) - r0);
    if (std::fabs(diff - 1.0) < 1e-9) continue;  // ties: tested exactly below
    const bool exact = arc_end_on_circle(x0, y0, uint64_t(x1), uint64_t(y1));
    ASSERT_EQ(exact, diff <= 1.0) << "start (" << x0 << ", " << y0 << ") end (" << x1 << ", "
                                  << y1 << "), radius difference " << diff;
    (exact ? accepted : rejected) += 1;
  }
  EXPECT_GT(accepted, 10000);
  EXPECT_GT(rejected, 10000);
}

TEST(ArcCheck, RadiusRuleAcceptsExactlyOneBluAndNotMore) {
  EXPECT_TRUE(arc_end_on_circle(5, 0, 4, 0));    // 5 -> 4
  EXPECT_TRUE(arc_end_on_circle(3, 4, 6, 0));    // 5 -> 6
  EXPECT_TRUE(arc_end_on_circle(1, 0, 0, 2));    // 1 -> 2
  EXPECT_FALSE(arc_end_on_circle(3, 4, 0, 7));   // 5 -> 7
  EXPECT_TRUE(arc_end_on_circle(6, 8, 9, 0));    // 10 -> 9
  EXPECT_TRUE(arc_end_on_circle(6, 8, 0, 11));   // 10 -> 11
  EXPECT_FALSE(arc_end_on_circle(6, 8, 1, 11));  // 10 -> sqrt(122) = 11.05
  EXPECT_FALSE(arc_end_on_circle(6, 8, 0, 8));   // 10 -> 8
}

// The serial radius check (rtl/arc_radius_check.sv's twin), run clock by clock from its
// start edge: its verdict is arc_end_on_circle()'s, and it is done after clocks(w) edges.
bool serial_radius_verdict(uint64_t x0, uint64_t y0, uint64_t x1, uint64_t y1, unsigned w) {
  const ArcGeometry g{x0, y0, x1, y1};  // the check reads only the magnitudes
  ArcRadiusCheck check(w);
  check.start();
  uint64_t edges = 0;
  while (!check.done() && edges <= ArcRadiusCheck::clocks(w)) {
    check.step(g);
    ++edges;
  }
  EXPECT_EQ(edges, ArcRadiusCheck::clocks(w));
  return check.ok();
}

TEST(ArcRadiusCheck, SerialVerdictEqualsTheExactRuleOnEveryFourBitArc) {
  const unsigned w = 4;
  int accepted = 0;
  for (uint64_t x0 = 0; x0 < 16; ++x0)
    for (uint64_t y0 = 0; y0 < 16; ++y0) {
      if (x0 == 0 && y0 == 0) continue;  // zero radius: the geometry's error 12 first
      for (uint64_t x1 = 0; x1 < 16; ++x1)
        for (uint64_t y1 = 0; y1 < 16; ++y1) {
          const bool exact = arc_end_on_circle(x0, y0, x1, y1);
          ASSERT_EQ(serial_radius_verdict(x0, y0, x1, y1, w), exact)
              << "start (" << x0 << ", " << y0 << ") end (" << x1 << ", " << y1 << ")";
          accepted += exact;
        }
    }
  EXPECT_GT(accepted, 1000);
}

TEST(ArcRadiusCheck, SerialVerdictEqualsTheExactRuleAtWideRegisters) {
  std::mt19937_64 rng(17);
  for (unsigned w : {16u, 24u, 31u}) {
    const uint64_t top = (uint64_t{1} << w) - 1;
    int accepted = 0, rejected = 0;
    for (int t = 0; t < 400; ++t) {
      const uint64_t x0 = rng() % (top + 1), y0 = 1 + rng() % top;
      // Ends near the circle (both verdicts) and anywhere (mostly far off).
      const double r0 = std::hypot(double(x0), double(y0));
      const double ang = double(rng() % 100000) / 100000.0 * M_PI / 2;
      const double r1 = t % 4 == 0 ? double(rng() % (top + 1))
                                   : r0 + (double(rng() % 4001) - 2000.0) / 1000.0;
      const uint64_t x1 = std::min<uint64_t>(top, uint64_t(std::llround(r1 * std::cos(ang))));
      const uint64_t y1 = std::min<uint64_t>(top, uint64_t(std::llround(r1 * std::sin(ang))));
      const bool exact = arc_end_on_circle(x0, y0, x1, y1);
      ASSERT_EQ(serial_radius_verdict(x0, y0, x1, y1, w), exact)
          << "W " << w << " start (" << x0 << ", " << y0 << ") end (" << x1 << ", " << y1 << ")";
      (exact ? accepted : rejected) += 1;
    }
    EXPECT_GT(accepted, 50) << "W " << w;
    EXPECT_GT(rejected, 50) << "W " << w;
  }
}

TEST(ArcCheck, FullQuadrantsAreInsideOneQuadrantOnlyInTheirDirection) {
  for (int q = 0; q < 4; ++q) {
    for (bool ccw : {false, true}) {
      const QuadrantArc a = full_quadrant(100, q, ccw);
      EXPECT_EQ(check_arc(a.words(), 16), TapeError::kNone) << a.describe();
      // The same ends travelled the other way round are three quadrants.
      QuadrantArc b = a;
      b.ccw = !ccw;
      EXPECT_EQ(check_arc(b.words(), 16), TapeError::kArcCrossesQuadrant) << b.describe();
    }
  }
}

TEST(ArcCheck, EndsOnAnAxisBelongToBothQuadrants) {
  // From +X into Q1 (ccw) and into Q4 (cw); a short arc from an axis point either way.
  EXPECT_EQ(check_arc(arc(100, 0, 99, 14, true).words(), 16), TapeError::kNone);
  EXPECT_EQ(check_arc(arc(100, 0, 99, -14, false).words(), 16), TapeError::kNone);
  EXPECT_EQ(check_arc(arc(0, 100, -14, 99, true).words(), 16), TapeError::kNone);
  EXPECT_EQ(check_arc(arc(0, -100, 14, -99, true).words(), 16), TapeError::kNone);
  // One grid step off an axis on the far side crosses it.
  EXPECT_EQ(check_arc(arc(100, -1, 99, 14, true).words(), 16), TapeError::kArcCrossesQuadrant);
  EXPECT_EQ(check_arc(arc(99, -14, 99, 14, true).words(), 16), TapeError::kArcCrossesQuadrant);
  EXPECT_EQ(check_arc(arc(14, 99, -14, 99, true).words(), 16), TapeError::kArcCrossesQuadrant);
  // Moving against the arc's direction inside one quadrant.
  EXPECT_EQ(check_arc(arc(99, 14, 100, 0, true).words(), 16), TapeError::kArcCrossesQuadrant);
  EXPECT_EQ(check_arc(arc(99, 14, 100, 0, false).words(), 16), TapeError::kNone);
}

TEST(ArcCheck, ErrorsComeInTheDecodersOrder) {
  // Zero radius first, even when the move is also bad.
  EXPECT_EQ(check_arc(ArcWords::from_signed(5, 5, 0, 0, true), 16), TapeError::kArcZeroRadius);
  EXPECT_EQ(check_arc(ArcWords::from_signed(0, 0, 0, 0, false), 16), TapeError::kArcZeroRadius);
  // A zero move is a full circle: not one quadrant.
  EXPECT_EQ(check_arc(ArcWords::from_signed(0, 0, -5, 0, true), 16),
            TapeError::kArcCrossesQuadrant);
  // Quadrant before width: this end is too wide and in another quadrant.
  EXPECT_EQ(check_arc(arc(-65535, 0, 1, 65535, false).words(), 16),
            TapeError::kArcCrossesQuadrant);
  // An end outside the W-bit register (here 2^16) is error 4.
  EXPECT_EQ(check_arc(arc(46341, 46341, 65536, 0, false).words(), 16), TapeError::kValueTooWide);
  EXPECT_EQ(check_arc(arc(46341, 46341, 65535, 0, false).words(), 16),
            TapeError::kArcEndpointOffCircle);
  // Off the circle last.
  EXPECT_EQ(check_arc(arc(100, 0, 0, 102, true).words(), 16), TapeError::kArcEndpointOffCircle);
  EXPECT_EQ(check_arc(arc(100, 0, 0, 101, true).words(), 16), TapeError::kNone);
}

TEST(ArcGeometry, LoadsMagnitudesGrowthCountsAndModulus) {
  const QuadrantArc a = arc(-300, 400, -500, 0, true);  // Q2, ccw: |x| grows, |y| shrinks
  const ArcGeometry g = arc_geometry(a.words(), 16);
  EXPECT_EQ(g.error, TapeError::kNone);
  EXPECT_EQ(g.x0, 300u);
  EXPECT_EQ(g.y0, 400u);
  EXPECT_EQ(g.x1, 500u);
  EXPECT_EQ(g.y1, 0u);
  EXPECT_TRUE(g.grow_x);
  EXPECT_FALSE(g.grow_y);
  EXPECT_EQ(g.cnt_x, 200u);
  EXPECT_EQ(g.cnt_y, 400u);
  EXPECT_EQ(g.k, 9u);  // 500 < 512
}

// The decoder's arc preparation: same verdict as check_arc(), N marked iterations (the
// decoder's S = F * N) with N the golden DDA's iteration count, and done in the clock after
// max(N, (5W + 4)(2W + 4)) run edges, max(2PN, ...) with the serial dry run (P = W rounded
// up to a power of two).
void expect_prepare(const QuadrantArc& a, unsigned w, bool serial) {
  ArcPrepare prep(w, serial);
  const ArcWords words = a.words();
  const TapeError want = check_arc(words, w);
  const ArcGeometry g = arc_geometry(words, w);
  uint64_t calls = 0, iterations = 0;
  ArcPrepare::Result r;
  while (!r.done && calls < (uint64_t{1} << 26)) {
    r = prep.edge(words);
    iterations += r.iterate;
    ++calls;
  }
  ASSERT_TRUE(r.done) << a.describe();
  EXPECT_EQ(r.error, want) << a.describe();
  const uint64_t geometry = serial ? w + 1 : 0;  // the geometry's serial pass
  if (g.error != TapeError::kNone) {
    EXPECT_EQ(calls, 1 + geometry) << a.describe();
    return;
  }
  const circle_study::ArcRunStats run = circle_study::run_arc(a, w, 1u << 20);
  const uint64_t check_steps = ArcRadiusCheck::clocks(w);  // (5W + 4)(2W + 4)
  if (want == TapeError::kNone) {
    EXPECT_EQ(iterations, run.iterations) << a.describe();
    EXPECT_EQ(calls, 1 + ArcPrepare::clocks(w, serial, run.iterations)) << a.describe();
    uint64_t pass = 1;
    while (pass < w) pass *= 2;
    const uint64_t dry = serial ? 2 * pass * run.iterations : run.iterations;
    EXPECT_EQ(calls, 2 + geometry + std::max(dry, check_steps)) << a.describe();
  } else {
    EXPECT_EQ(calls, 2 + geometry + check_steps) << a.describe();  // the dry run is cut short
  }
}

TEST(ArcPrepare, VerdictIterationsAndTimingOfGoodAndBadArcs) {
  for (bool serial : {false, true}) {
    std::mt19937_64 rng(5);
    for (int t = 0; t < 300; ++t) {
      QuadrantArc a = circle_study::random_arc(rng, serial ? 4095 : 65535);
      if (t % 3 == 1) a.x1 += int64_t(rng() % 5) - 2;  // some ends off the circle
      if (t % 7 == 2) a.ccw = !a.ccw;                   // some arcs the long way round
      expect_prepare(a, 16, serial);
    }
    expect_prepare(arc(1, 0, 0, 1, true), 16, serial);
    expect_prepare(arc(0, 0, 0, 1, true), 16, serial);
    expect_prepare(arc(5, 0, 0, 5, true), 4, serial);
  }
}

}  // namespace
}  // namespace ncinterp
