// PlayMonitor on synthetic output sequences (each measurement can be made to fail) and on
// golden-model runs of random line tapes (the documented guarantees: exact pulses and
// position, every pulse within the L1 bound of its chord, block time late by less than one
// clock).
#include <gtest/gtest.h>

#include <random>

#include "frame_source.h"
#include "interp_top.h"
#include "path_bounds.h"
#include "play_monitor.h"
#include "play_run.h"

namespace ncinterp::system {
namespace {

tape::Program program_of(std::vector<tape::Block> blocks) {
  tape::Program p;
  p.blocks = std::move(blocks);
  return p;
}

// Feeds a script of per-clock outputs; cycle 0 is the state after reset.
struct Script {
  std::vector<InterpOutputs> clocks;
  InterpOutputs cur;
  void clock(int n = 1) {
    for (int k = 0; k < n; ++k) {
      clocks.push_back(cur);
      cur.step_x = cur.step_y = false;
    }
  }
  void step(bool x, bool y) {
    if (x) {
      cur.step_x = true;
      cur.pos_x += cur.dir_x ? 1 : -1;
    }
    if (y) {
      cur.step_y = true;
      cur.pos_y += cur.dir_y ? 1 : -1;
    }
    clock();
  }
  PlaySummary run(const tape::Program& p, uint64_t modulus) {
    InterpConfig cfg;
    cfg.feed_modulus = modulus;
    PlayMonitor m(p, cfg);
    for (size_t c = 0; c < clocks.size(); ++c) m.observe(c, clocks[c]);
    return m.finish(clocks.back());
  }
};

TEST(PlayMonitor, CountsPulsesGapsAndTiming) {
  // Two blocks: N1 X+2 (F = M/4: ideal 4 clocks), a 2-clock gap, N2 Y-1 (ideal 4 clocks).
  const auto p = program_of({{1, tape::Motion::kLine, 2, 0, 0, 0, 250}, {2, tape::Motion::kLine, 0, -1, 0, 0, 250}});
  Script s;
  s.clock();         // cycle 0: reset
  s.clock(3);        // cycles 1-3: lead-in
  s.cur.busy = true; s.cur.block_n = 1; s.cur.dir_x = true;
  s.clock();         // cycle 4: load N1
  s.step(true, false);
  s.clock();
  s.step(true, false);
  s.clock();         // cycle 8: finishing clock
  s.cur.busy = false;
  s.clock(2);        // cycles 9-10: gap (N1 took 9 - 4 = 5 clocks)
  s.cur.busy = true; s.cur.block_n = 2; s.cur.dir_y = false;
  s.clock();         // cycle 11: load N2
  s.step(false, true);
  s.clock(2);
  s.cur.busy = false;
  s.clock();         // cycle 15: N2 ended (4 clocks)
  s.cur.done = true;
  s.clock();
  const PlaySummary r = s.run(p, 1000);
  EXPECT_TRUE(r.done);
  EXPECT_EQ(r.pulses_x.plus, 2u);
  EXPECT_EQ(r.pulses_x.minus, 0u);
  EXPECT_EQ(r.pulses_y.minus, 1u);
  EXPECT_EQ(r.final_x, 2);
  EXPECT_EQ(r.final_y, -1);
  EXPECT_EQ(r.lead_in_cycles, 3u);
  EXPECT_EQ(r.gap_cycles, 2u);
  EXPECT_EQ(r.blocks_played, 2u);
  ASSERT_EQ(r.timeline.size(), 2u);
  EXPECT_EQ(r.timeline[0].cycles(), 5u);
  EXPECT_EQ(r.timeline[1].cycles(), 4u);
  EXPECT_EQ(r.timed_blocks, 2u);
  EXPECT_DOUBLE_EQ(r.worst_time_error_cycles, 1.0);
  EXPECT_DOUBLE_EQ(r.worst_relative_time_error, 0.25);
  EXPECT_EQ(r.worst_time_error_block, 1u);
  EXPECT_EQ(r.max_path_error, 0.0);  // axis-parallel moves: every pulse is on the chord
  EXPECT_TRUE(r.path_within_bound);
}

TEST(PlayMonitor, PathErrorIsTheDistanceToTheProgrammedChord) {
  // N1 X+2 Y+2, but the engine steps X twice first: (1,0) is sqrt(2)/2 from the diagonal,
  // within the L1 bound sqrt(2)/2; (2,0) is sqrt(2) away: beyond it.
  const auto p = program_of({{1, tape::Motion::kLine, 2, 2, 0, 0, 100}});
  Script s;
  s.clock();
  s.cur.busy = true; s.cur.block_n = 1; s.cur.dir_x = s.cur.dir_y = true;
  s.clock();
  s.step(true, false);
  s.step(true, false);
  s.step(false, true);
  s.step(false, true);
  const PlaySummary r = s.run(p, 1000);
  EXPECT_NEAR(r.max_path_error, std::sqrt(2.0), 1e-12);
  EXPECT_FALSE(r.path_within_bound);
  EXPECT_EQ(r.max_path_error_block, 1u);
  EXPECT_EQ(r.final_x, 2);
  EXPECT_EQ(r.final_y, 2);
}

TEST(PlayMonitor, ExtraPulsesAreCaught) {
  const auto p = program_of({{1, tape::Motion::kLine, 1, 0, 0, 0, 100}});
  Script s;
  s.clock();
  s.cur.busy = true; s.cur.block_n = 1; s.cur.dir_x = true;
  s.step(true, false);
  s.step(true, false);  // one pulse more than programmed
  const PlaySummary r = s.run(p, 1000);
  EXPECT_EQ(r.pulses_beyond_program, 1u);
  EXPECT_FALSE(r.path_within_bound);
  EXPECT_DOUBLE_EQ(r.max_path_error, 1.0);
}

TEST(PlayMonitor, SameNumberBlocksSplitByAGap) {
  // N5, N5 (gap between), N5 + N6 back to back: three observed blocks, matched 1, 1+?; the
  // last N5 run before N6 has one block.
  const auto p = program_of({{5, tape::Motion::kLine, 1, 0, 0, 0, 100},
                             {5, tape::Motion::kLine, 2, 0, 0, 0, 100},
                             {6, tape::Motion::kLine, 3, 0, 0, 0, 100}});
  Script s;
  s.clock();
  s.cur.dir_x = true;
  s.cur.busy = true; s.cur.block_n = 5;
  s.step(true, false);
  s.clock();
  s.cur.busy = false;
  s.clock();
  s.cur.busy = true;
  s.step(true, false);
  s.step(true, false);
  s.clock();
  s.cur.block_n = 6;
  s.step(true, false);
  s.step(true, false);
  s.step(true, false);
  s.cur.busy = false;
  s.clock();
  const PlaySummary r = s.run(p, 1000);
  ASSERT_EQ(r.timeline.size(), 3u);
  EXPECT_EQ(r.timeline[0].block_count, 1u);
  EXPECT_EQ(r.timeline[1].block_count, 1u);
  EXPECT_EQ(r.timeline[1].first_block, 1u);
  EXPECT_EQ(r.timeline[2].first_block, 2u);
  EXPECT_EQ(r.blocks_played, 3u);
}

TEST(PlayMonitor, PathBoundFormula) {
  EXPECT_DOUBLE_EQ(line_path_bound(10, 0), 0.5);
  EXPECT_NEAR(line_path_bound(7, 7), std::sqrt(2.0) / 2, 1e-12);
  EXPECT_DOUBLE_EQ(line_path_bound(0, 0), 0.0);
  EXPECT_DOUBLE_EQ(distance_to_segment(3, 4, 10, 0), 4.0);
  EXPECT_DOUBLE_EQ(distance_to_segment(-3, 4, 10, 0), 5.0);  // before the start point
}

// Golden model runs of random line tapes: the monitor confirms the documented guarantees.
TEST(PlayMonitor, GoldenRunsMeetTheGuarantees) {
  std::mt19937_64 rng(5);
  size_t saturated = 0, timed = 0;
  for (int trial = 0; trial < 40; ++trial) {
    SCOPED_TRACE(trial);
    const double clock_hz = 2000;  // M = 1.2e8: 545..6000 clocks per block
    // The parallel arch: one iteration per clock, so both regimes at these feeds.
    InterpConfig cfg = interp_config(clock_hz);
    cfg.arch = Arch::kParallel;
    tape::Program p;
    const int blocks = 1 + static_cast<int>(rng() % 8);
    for (int k = 0; k < blocks; ++k) {
      tape::Block b;
      b.n = static_cast<uint32_t>(k + 1);
      b.dx = static_cast<int64_t>(rng() % 2001) - 1000;
      b.dy = static_cast<int64_t>(rng() % 2001) - 1000;
      b.feed = 20000 + rng() % 200000;  // 20..220 /min; saturated when F 2^k >= M
      p.blocks.push_back(b);
    }
    const auto frames = tape::add_parity(tape::format_program(p, tape::Format{}));
    GoldenInterp dut(cfg);
    dut.reset();
    FrameSource source(frames, FrameSource::cycles_per_frame_for(clock_hz, 2000));
    PlayMonitor m(p, cfg);
    m.observe(0, dut.outputs());
    while (!m.finished() && dut.cycle() < 50'000'000) {
      const bool ready = dut.outputs().frame_ready;
      dut.tick(source.inputs());
      source.clock(ready);
      m.observe(dut.cycle(), dut.outputs());
    }
    const PlaySummary r = m.finish(dut.outputs());
    ASSERT_TRUE(r.done);
    EXPECT_EQ(r.final_x, r.expected_x);
    EXPECT_EQ(r.final_y, r.expected_y);
    EXPECT_TRUE(r.path_within_bound);
    EXPECT_EQ(r.pulses_beyond_program, 0u);
    EXPECT_EQ(r.blocks_played, p.blocks.size());
    EXPECT_EQ(r.timed_blocks + r.saturated_blocks, p.blocks.size());
    saturated += r.saturated_blocks;
    timed += r.timed_blocks;
    for (const BlockTiming& t : r.timeline) {
      if (t.saturated) continue;
      const double late = static_cast<double>(t.cycles()) - t.ideal_cycles;
      EXPECT_GE(late, 0.0) << "N" << t.n;
      EXPECT_LT(late, 1.0) << "N" << t.n;
    }
  }
  EXPECT_GT(saturated, 10u);  // both regimes are exercised
  EXPECT_GT(timed, 10u);
}

}  // namespace
}  // namespace ncinterp::system
