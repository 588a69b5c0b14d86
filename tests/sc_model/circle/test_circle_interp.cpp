// Circle mode in the whole golden interpolator (GoldenInterp): a 50 mm circle of four
// quadrant blocks returns exactly to its start within 1 BLU of the circle, ten turns do not
// drift, random programs of arcs and lines play exactly with the documented block times,
// bad arcs stop the machine with their error, block and offset and no pulse, and the arc's
// preparation in the decoder takes the documented clocks.
#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <string>

#include "arc_geometry.h"
#include "circle_program.h"
#include "arc_cases.h"
#include "interp_top.h"
#include "interp_test_support.h"

namespace ncinterp {
namespace {

using test::BlockClocks;
using test::OutputRecorder;

constexpr uint64_t kMaxCycles = 200'000'000;

struct PlayRun {
  OutputRecorder rec;
  BlockClocks clocks;
  InterpOutputs out;
};

PlayRun play(const InterpConfig& cfg, const std::vector<uint8_t>& frames, uint64_t cycles_per_frame = 1) {
  GoldenInterp dut(cfg);
  PlayRun r;
  FrameSource source(frames, cycles_per_frame);
  r.rec.observe(0, dut.outputs());
  while (!dut.outputs().done && !dut.outputs().error && dut.cycle() < kMaxCycles) {
    const bool ready = dut.outputs().frame_ready;
    dut.tick(source.inputs());
    source.clock(ready);
    r.rec.observe(dut.cycle(), dut.outputs());
    r.clocks.observe(dut.outputs());
  }
  r.out = dut.outputs();
  return r;
}

tape::Block quadrant_block(uint32_t n, int64_t r, int q, bool ccw, uint64_t feed) {
  const circle_study::QuadrantArc a = circle_study::full_quadrant(r, q, ccw);
  tape::Block b;
  b.n = n;
  b.motion = ccw ? tape::Motion::kArcCcw : tape::Motion::kArcCw;
  b.i = -a.x0;
  b.j = -a.y0;
  b.dx = a.x1 - a.x0;
  b.dy = a.y1 - a.y0;
  b.feed = feed;
  return b;
}

// Circle of radius 50 mm (50000 BLU) about the origin, starting at (50000, 0), as four
// quadrant blocks per turn; F = 300/min: each block takes 0.2 s, 200000 clocks at 1 MHz.
tape::Program circle_program(int turns, bool ccw) {
  tape::Program p;
  uint32_t n = 1;
  for (int t = 0; t < turns; ++t)
    for (int q = 0; q < 4; ++q)
      p.blocks.push_back(quadrant_block(n++, 50000, ccw ? q : 3 - q, ccw, 300000));
  return p;
}

// Radial distance of every pulse position from the circle of radius 50000 about
// (-50000, 0) (the tool starts at the origin, on the circle's +X point).
double max_circle_error(const OutputRecorder& rec) {
  double worst = 0;
  for (const auto& p : rec.pulses)
    worst = std::max(worst, std::fabs(std::hypot(double(p.x + 50000), double(p.y)) - 50000.0));
  return worst;
}

// Each arch at a clock where a quadrant (N = 102944 iterations in 0.2 s) is not saturated:
// the parallel one at 1 MHz, the serial one (2P = 32 clocks per iteration) at 20 MHz.
InterpConfig unsaturated_circle_machine(Arch arch) {
  InterpConfig cfg = interp_config(arch == Arch::kSerial ? 20e6 : 1e6);
  cfg.arch = arch;
  return cfg;
}

// Clocks of the 0.2 s (1/F) a quadrant takes on that machine.
uint64_t quadrant_clocks(const InterpConfig& cfg) { return cfg.feed_modulus / 300000; }

TEST(CircleInterp, FiftyMillimetreCircleOfFourQuadrantsReturnsToItsStart) {
  for (Arch arch : {Arch::kSerial, Arch::kParallel}) {
    SCOPED_TRACE(arch_name(arch));
    const InterpConfig cfg = unsaturated_circle_machine(arch);
    for (bool ccw : {true, false}) {
      const tape::Program p = circle_program(1, ccw);
      PlayRun r = play(cfg, test::program_frames(p));
      ASSERT_TRUE(r.out.done) << "error " << int(r.out.error_code);
      EXPECT_EQ(r.out.pos_x, 0);
      EXPECT_EQ(r.out.pos_y, 0);
      ASSERT_TRUE(test::check_program_run(p, r.rec, r.clocks, cfg));
      EXPECT_LE(max_circle_error(r.rec), kCircleDdaBound);
      // No gaps: the four blocks follow each other (0.2 s each, 1/F).
      EXPECT_EQ(r.rec.busy_cycles, 4 * quadrant_clocks(cfg));
      ASSERT_EQ(r.rec.starts.size(), 4u);
      for (int i = 1; i < 4; ++i)
        EXPECT_EQ(r.rec.starts[i].cycle - r.rec.starts[i - 1].cycle, quadrant_clocks(cfg));
    }
  }
}

TEST(CircleInterp, TenTurnsDoNotDrift) {
  const InterpConfig cfg = unsaturated_circle_machine(Arch::kSerial);
  const tape::Program p = circle_program(10, true);
  PlayRun r = play(cfg, test::program_frames(p));
  ASSERT_TRUE(r.out.done);
  EXPECT_EQ(r.out.pos_x, 0);
  EXPECT_EQ(r.out.pos_y, 0);
  ASSERT_TRUE(test::check_program_run(p, r.rec, r.clocks, cfg));
  // Each turn's pulses are the first turn's, shifted by one turn's duration.
  const size_t per_turn = r.rec.pulses.size() / 10;
  ASSERT_EQ(r.rec.pulses.size(), 10 * per_turn);
  const uint64_t period = 4 * quadrant_clocks(cfg);
  for (size_t i = 0; i < r.rec.pulses.size(); ++i) {
    const auto& a = r.rec.pulses[i % per_turn];
    const auto& b = r.rec.pulses[i];
    ASSERT_EQ(b.cycle - a.cycle, (i / per_turn) * period) << "pulse " << i;
    ASSERT_EQ(b.x, a.x);
    ASSERT_EQ(b.y, a.y);
  }
  EXPECT_LE(max_circle_error(r.rec), kCircleDdaBound);
}

TEST(CircleInterp, RandomProgramsOfArcsAndLines) {
  const InterpConfig cfg = interp_config(1e3);  // saturates high feeds, short runs
  std::mt19937_64 rng(21);
  int arcs = 0;
  for (int t = 0; t < 20; ++t) {
    const tape::Program p = test::random_arc_program(rng, 20, 0.8, cfg.feed_modulus);
    for (const auto& b : p.blocks) arcs += tape::is_arc(b.motion);
    PlayRun r = play(cfg, test::program_frames(p), 1 + rng() % 3);
    ASSERT_TRUE(r.out.done) << "tape " << t << ": error " << int(r.out.error_code) << " block "
                            << r.out.error_block;
    ASSERT_TRUE(test::check_program_run(p, r.rec, r.clocks, cfg)) << "tape " << t;
  }
  EXPECT_GT(arcs, 250);
}

// A bad arc after two good blocks: the machine plays the good ones, stops with the arc's
// error code, N and the offset of its LF, and emits no pulse from it.
struct BadArc {
  std::string words;  // the bad block's words after "N3 "
  TapeError code;
};

TEST(CircleInterp, BadArcsStopWithTheirErrorAndNoPulse) {
  const InterpConfig cfg = interp_config(1e6);
  const std::vector<BadArc> cases = {
      {"G03 X-1.000 Y1.000 I0.000 J0.000 F100.000", TapeError::kArcZeroRadius},
      {"G02 X-1.000 Y1.000 I-1.000 J0.000 F100.000", TapeError::kArcCrossesQuadrant},
      {"G03 X0.000 Y0.000 I-1.000 J0.000 F100.000", TapeError::kArcCrossesQuadrant},
      {"G03 X-1.000 Y1.100 I-1.000 J0.000 F100.000", TapeError::kArcEndpointOffCircle},
      {"G03 X-0.100 Y-0.002 I-0.100 J0.000 F100.000", TapeError::kArcCrossesQuadrant},
      {"G02 X65.535 Y-46.341 I-0.001 J-46.341 F100.000", TapeError::kValueTooWide},
  };
  for (const BadArc& c : cases) {
    const std::string head =
        "%\nG17 G21 G91 G93\nN1 G01 X1.000 Y0.500 F600.000\nN2 G03 X-0.500 Y0.500 I-0.500 "
        "J0.000 F600.000\n";
    const std::string bad = "N3 " + c.words + "\n";
    const std::string text = head + bad + "N4 G01 X1.000 F600.000\nM02\n%\n";
    PlayRun r = play(cfg, test::frames_of(text));
    ASSERT_TRUE(r.out.error) << c.words;
    EXPECT_EQ(r.out.error_code, static_cast<uint8_t>(c.code)) << c.words;
    EXPECT_EQ(r.out.error_block, 3u) << c.words;
    EXPECT_EQ(r.out.error_offset, head.size() + bad.size() - 1) << c.words;  // its LF
    EXPECT_EQ(r.out.pos_x, 1000 - 500) << c.words;
    EXPECT_EQ(r.out.pos_y, 500 + 500) << c.words;
    for (const auto& p : r.rec.pulses) ASSERT_LT(p.block, 3u) << c.words;
  }
}

// G02/G03 are modal like G01, and an arc block needs I or J only when they are not 0.
TEST(CircleInterp, ArcMotionIsModal) {
  const InterpConfig cfg = interp_config(1e6);
  const std::string text =
      "%\nG17 G21 G91 G93\nN1 G03 X-0.005 Y0.005 I-0.005 F600.000\nN2 X-0.005 Y-0.005 J-0.005\n"
      "N3 G01 X0.010\nM02\n%\n";
  PlayRun r = play(cfg, test::frames_of(text));
  ASSERT_TRUE(r.out.done) << int(r.out.error_code);
  EXPECT_EQ(r.out.pos_x, 0);
  EXPECT_EQ(r.out.pos_y, 0);
}

}  // namespace
}  // namespace ncinterp
