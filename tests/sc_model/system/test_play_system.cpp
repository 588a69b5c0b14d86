// The SystemC system model, in process: each test is one SystemC simulation, so ctest runs
// each in its own process (gtest_discover_tests); running this binary without a filter
// runs only the first SystemC test successfully.
// Checks: a SystemC run sees exactly what a plain C++ golden run sees, clock for clock
// (reader timing, reset and sampling add nothing), for the golden and the RTL engine; the
// VCD window lands on the documented edges; a bad tape leaves no VCD.
#include <gtest/gtest.h>

#include "frame_source.h"
#include "interp_top.h"
#include "play_run.h"
#include "scratch_dir_test.h"
#include "vcd_header.h"

namespace ncinterp::system {
namespace {

constexpr double kClockHz = 1e5;
constexpr double kReaderCps = 5000;  // 20 clocks per frame

// A five-pointed star (five chords, 67..120 ms each at 100 kHz, not saturated), a dwell, and
// a long saturated move.
tape::Program star() {
  tape::Program p;
  const int64_t pts[][2] = {{0, 0},     {1176, 3618}, {2351, 0},    {-727, 2236}, {3078, 2236},
                            {0, 0}};
  for (int k = 0; k < 5; ++k)
    p.blocks.push_back({static_cast<uint32_t>(10 * (k + 1)), tape::Motion::kLine,
                        pts[k + 1][0] - pts[k][0], pts[k + 1][1] - pts[k][1], 0, 0,
                        500'000 + 100'000 * static_cast<uint64_t>(k)});
  p.blocks.push_back({60, tape::Motion::kLine, 0, 0, 0, 0, 4'000'000});  // a dwell
  p.blocks.push_back({70, tape::Motion::kLine, 40000, -1, 0, 0, 90'000'000});  // saturated
  return p;
}

std::vector<uint8_t> frames_of(const tape::Program& p) {
  return tape::add_parity(tape::format_program(p, tape::Format{}));
}

// The same tape on the plain C++ golden model with the same reader timing.
PlaySummary plain_golden_run(const std::vector<uint8_t>& frames, const tape::Program& p) {
  const InterpConfig cfg = interp_config(kClockHz);
  GoldenInterp dut(cfg);
  dut.reset();
  FrameSource source(frames, FrameSource::cycles_per_frame_for(kClockHz, kReaderCps));
  PlayMonitor m(p, cfg);
  m.observe(0, dut.outputs());
  while (!m.finished() && dut.cycle() < 100'000'000) {
    const bool ready = dut.outputs().frame_ready;
    dut.tick(source.inputs());
    source.clock(ready);
    m.observe(dut.cycle(), dut.outputs());
  }
  return m.finish(dut.outputs());
}

PlayOptions options(EngineKind engine) {
  PlayOptions o;
  o.engine = engine;
  o.clock_hz = kClockHz;
  o.reader_cps = kReaderCps;
  return o;
}

void expect_same_run(const PlaySummary& a, const PlaySummary& b) {
  EXPECT_EQ(a.cycles, b.cycles);
  EXPECT_EQ(a.done, b.done);
  EXPECT_EQ(a.pulses_x.plus, b.pulses_x.plus);
  EXPECT_EQ(a.pulses_x.minus, b.pulses_x.minus);
  EXPECT_EQ(a.pulses_y.plus, b.pulses_y.plus);
  EXPECT_EQ(a.pulses_y.minus, b.pulses_y.minus);
  EXPECT_EQ(a.final_x, b.final_x);
  EXPECT_EQ(a.final_y, b.final_y);
  EXPECT_EQ(a.max_path_error, b.max_path_error);
  EXPECT_EQ(a.gap_cycles, b.gap_cycles);
  EXPECT_EQ(a.lead_in_cycles, b.lead_in_cycles);
  EXPECT_EQ(a.busy_cycles, b.busy_cycles);
  ASSERT_EQ(a.timeline.size(), b.timeline.size());
  for (size_t k = 0; k < a.timeline.size(); ++k) {
    EXPECT_EQ(a.timeline[k].n, b.timeline[k].n);
    EXPECT_EQ(a.timeline[k].load_cycle, b.timeline[k].load_cycle);
    EXPECT_EQ(a.timeline[k].end_cycle, b.timeline[k].end_cycle);
  }
}

void play_matches_plain_golden(EngineKind engine) {
  const tape::Program p = star();
  const auto frames = frames_of(p);
  const PlaySummary reference = plain_golden_run(frames, p);
  ASSERT_TRUE(reference.done);
  const PlayResult r = run_play(frames, p, options(engine));
  ASSERT_TRUE(r.ok());
  expect_same_run(r.summary, reference);
  // And against the tape itself.
  EXPECT_EQ(r.summary.final_x, 40000);
  EXPECT_EQ(r.summary.final_y, -1);
  EXPECT_TRUE(r.summary.path_within_bound);
  EXPECT_EQ(r.summary.blocks_played, p.blocks.size());
  // Both regimes: the blocks the plain model saturates (the serial arch, the default,
  // iterates at most every 2P clocks, so more of them), and timed ones.
  EXPECT_EQ(r.summary.saturated_blocks, reference.saturated_blocks);
  EXPECT_GE(r.summary.saturated_blocks, 1u);
  EXPECT_LT(r.summary.saturated_blocks, p.blocks.size());
  EXPECT_LT(r.summary.worst_time_error_cycles, 1.0);
  EXPECT_GE(r.summary.worst_time_error_cycles, 0.0);
}

TEST(PlaySystem, GoldenEngineSeesWhatThePlainGoldenModelSees) {
  play_matches_plain_golden(EngineKind::kGolden);
}

TEST(PlaySystem, RtlEngineSeesWhatThePlainGoldenModelSees) {
  play_matches_plain_golden(EngineKind::kRtl);
}

using PlayFiles = ncinterp::test::ScratchDirTest;

// Window N20..N30: opens half a clock before the load edge of N20, closes half a clock
// after the end edge of N30; edge c is at (c + 1) periods (the reset edge is at one period).
void window_lands_on_block_edges(EngineKind engine, const std::string& vcd) {
  const tape::Program p = star();
  const auto frames = frames_of(p);
  const PlaySummary reference = plain_golden_run(frames, p);
  PlayOptions o = options(engine);
  o.vcd_path = vcd;
  o.vcd_from = parse_vcd_bound("N20");
  o.vcd_to = parse_vcd_bound("N30");
  const PlayResult r = run_play(frames, p, o);
  ASSERT_TRUE(r.ok());
  ASSERT_TRUE(r.vcd_written);
  const uint64_t from = reference.timeline[1].load_cycle, to = reference.timeline[2].end_cycle;
  EXPECT_EQ(r.vcd_window.from, from);
  EXPECT_EQ(r.vcd_window.to, to);
  const uint64_t period_ps = 10'000'000;  // 100 kHz
  const std::vector<uint64_t> times = test::vcd_times(vcd);
  ASSERT_FALSE(times.empty());
  EXPECT_GE(times.front(), from * period_ps + period_ps / 2);
  EXPECT_LE(times.back(), (to + 1) * period_ps + period_ps / 2);
  EXPECT_NE(std::find(times.begin(), times.end(), (from + 1) * period_ps), times.end());
  EXPECT_NE(std::find(times.begin(), times.end(), (to + 1) * period_ps), times.end());
  const auto signals = test::vcd_signals(vcd);
  EXPECT_EQ(signals.at("SystemC.interp.interp_top.block_n_o"), 20);
  EXPECT_EQ(signals.at("SystemC.interp.interp_top.pos_x_o"), 32);
}

TEST_F(PlayFiles, GoldenVcdWindowByBlocks) {
  window_lands_on_block_edges(EngineKind::kGolden, path("g.vcd"));
  EXPECT_EQ(files().size(), 1u);
}

TEST_F(PlayFiles, RtlVcdWindowByBlocks) {
  window_lands_on_block_edges(EngineKind::kRtl, path("r.vcd"));
  EXPECT_EQ(files().size(), 1u);
}

TEST_F(PlayFiles, BadTapeStopsAtTheBlockAndLeavesNoVcd) {
  const tape::Program p = star();
  std::string text = tape::format_program(p, tape::Format{});
  const size_t bad = text.find("N40") + 4;  // "N40 Q01 ...": unknown letter in block N40
  text[bad] = 'Q';
  const auto frames = tape::add_parity(text);
  const tape::ParseResult readback = tape::parse_frames_partial(frames, tape_format_of(interp_config(kClockHz)));
  ASSERT_TRUE(readback.error);
  PlayOptions o = options(EngineKind::kGolden);
  o.vcd_path = path("bad.vcd");
  const PlayResult r = run_play(frames, readback.program, o);
  EXPECT_FALSE(r.ok());
  EXPECT_TRUE(r.summary.error);
  EXPECT_EQ(r.summary.error_code, 2);
  EXPECT_EQ(r.summary.error_block, 40u);
  EXPECT_EQ(r.summary.error_offset, bad);
  EXPECT_EQ(readback.error->offset, bad);
  // Blocks N10..N30 played completely, nothing of N40.
  EXPECT_EQ(r.summary.blocks_played, 3u);
  EXPECT_EQ(r.summary.final_x, 2351 + (-727 - 2351));
  EXPECT_EQ(r.summary.final_y, 2236);
  EXPECT_FALSE(r.vcd_written);
  EXPECT_EQ(files().size(), 0u);
}

TEST_F(PlayFiles, WindowOnABlockThatNeverPlaysIsAnError) {
  const tape::Program p = star();
  PlayOptions o = options(EngineKind::kGolden);
  o.vcd_path = path("w.vcd");
  o.vcd_from = parse_vcd_bound("N99");
  EXPECT_THROW(run_play(frames_of(p), p, o), std::runtime_error);
  EXPECT_EQ(files().size(), 0u);
}

TEST(PlaySystem, VcdBoundParsing) {
  EXPECT_EQ(parse_vcd_bound("1000").kind, VcdBound::Kind::kCycle);
  EXPECT_EQ(parse_vcd_bound("1000").value, 1000u);
  EXPECT_EQ(parse_vcd_bound("N12").kind, VcdBound::Kind::kBlock);
  EXPECT_EQ(parse_vcd_bound("N12").value, 12u);
  EXPECT_THROW(parse_vcd_bound("X12"), std::invalid_argument);
  EXPECT_THROW(parse_vcd_bound("N"), std::invalid_argument);
  EXPECT_THROW(parse_vcd_bound("-5"), std::invalid_argument);
  EXPECT_THROW(parse_vcd_bound(""), std::invalid_argument);
}

}  // namespace
}  // namespace ncinterp::system
