// Unit tests of the golden cycle model against the timing and rules of
// docs/interpolator.md: handshake, block latency, feed timing, DDA pulses, gaps, errors,
// fault hook, and random line tapes checked against the programmed increments. The tests
// of clock-exact formulas are the parallel arch's (one iteration per clock, where the
// formulas are shortest); the serial arch's clocks are the lock-step tests' against its RTL
// and the trajectory checker's schedule rules (tests/sc_model/checker).
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdlib>
#include <random>
#include <string>
#include <vector>

#include "interp_top.h"
#include "interp_test_support.h"

namespace ncinterp {
namespace {

using test::check_line_program;
using test::frames_of;
using test::LineBlock;
using test::OutputRecorder;

constexpr uint64_t kMaxCycles = 50'000'000;

uint64_t ceil_div(uint64_t a, uint64_t b) { return (a + b - 1) / b; }

// The parallel arch at this clock: the machine the clock-exact formulas below describe.
InterpConfig parallel_at(double clock_hz) {
  InterpConfig cfg = interp_config(clock_hz);
  cfg.arch = Arch::kParallel;
  return cfg;
}

unsigned bit_length(uint64_t x) {
  unsigned k = 0;
  while (x >> k) ++k;
  return k;
}

TEST(GoldenInterp, OutputsAfterResetAreIdle) {
  GoldenInterp dut(InterpConfig{});
  InterpOutputs expected;
  expected.frame_ready = true;
  EXPECT_EQ(dut.outputs(), expected);
  EXPECT_EQ(dut.cycle(), 0u);
}

TEST(GoldenInterp, RejectsWidthsItCannotModel) {
  InterpConfig cfg;
  cfg.inc_width = 33;
  EXPECT_THROW(GoldenInterp{cfg}, std::invalid_argument);
}

// The widest register the model takes (the bit-width sweep goes to W = 32): a block with
// |dx| = 2^32 - 1 has k = 32, so 2^k and acc + inc need 33 bits. Saturated, it makes one
// iteration per clock, and after j iterations X has exactly j pulses (2^31 + j (2^32 - 1)
// < (j + 1) 2^32) and Y, with |dy| = 2^31, floor((j + 1) / 2).
TEST(GoldenInterp, PlaysAFullWidthBlockAt32Bits) {
  InterpConfig cfg = parallel_at(1e6);
  cfg.inc_width = 32;
  const char* tape = "%\nG17 G21 G91 G93\nN1 G01 X4294967.295 Y-2147483.648 F4000000.000\nM02\n%\n";
  GoldenInterp dut(cfg);
  OutputRecorder rec;
  const InterpOutputs out = run_golden(dut, frames_of(tape), 1, 300, rec);
  ASSERT_FALSE(out.error) << "error code " << int(out.error_code);
  ASSERT_EQ(rec.starts.size(), 1u);
  EXPECT_TRUE(rec.starts[0].saturated);
  const int64_t j = static_cast<int64_t>(dut.cycle() - rec.starts[0].cycle);
  ASSERT_GT(j, 100);
  EXPECT_EQ(out.pos_x, j);
  EXPECT_EQ(out.pos_y, -((j + 1) / 2));
}

// One block, not saturated: pulses come exactly at the iterations the phase accumulator
// and the integrators dictate (docs 5.2/5.3), and the block takes ceil(M/F) clocks.
TEST(GoldenInterp, SingleBlockPulseTimesFollowTheFeedAndDdaFormulas) {
  const InterpConfig cfg = parallel_at(1e6);
  const std::vector<LineBlock> prog = {{1, 1000, -500, 600000}};
  GoldenInterp dut(cfg);
  OutputRecorder rec;
  const InterpOutputs out = run_golden(dut, frames_of(test::line_tape_text(prog)), 1, kMaxCycles, rec);
  ASSERT_TRUE(out.done);
  ASSERT_TRUE(check_line_program(prog, rec));
  ASSERT_EQ(rec.starts.size(), 1u);
  const uint64_t load = rec.starts[0].cycle;
  const uint64_t m = cfg.feed_modulus, f = 600000;
  const unsigned k = bit_length(1000 | 500);
  const uint64_t kpow = 1ull << k, s = f << k;
  ASSERT_LT(s, m);
  EXPECT_EQ(rec.busy_cycles, ceil_div(m, f));  // 100000 clocks = 1/600 min at 1 MHz
  std::vector<OutputRecorder::Pulse> expected;
  for (uint64_t j = 1; j <= kpow; ++j) {
    const uint64_t cycle = load + ceil_div(j * m, s) - 1;
    for (int a = 0; a < 2; ++a) {
      const uint64_t d = a == 0 ? 1000 : 500;
      if ((kpow / 2 + j * d) / kpow != (kpow / 2 + (j - 1) * d) / kpow)
        expected.push_back({cycle, 1, a, a == 0, 0, 0});
    }
  }
  ASSERT_EQ(rec.pulses.size(), expected.size());
  for (size_t i = 0; i < expected.size(); ++i) {
    EXPECT_EQ(rec.pulses[i].cycle, expected[i].cycle) << "pulse " << i;
    EXPECT_EQ(rec.pulses[i].axis, expected[i].axis) << "pulse " << i;
  }
}

TEST(GoldenInterp, BlockDurationRoundsTheProgrammedTimeUp) {
  InterpConfig cfg;
  cfg.feed_modulus = InterpConfig::feed_modulus_for(1000.0, 3);  // 1 kHz clock: M = 6e7
  for (uint64_t f : {7000ull, 12345ull, 59999ull}) {
    const std::vector<LineBlock> prog = {{5, 3, 2, f}};
    GoldenInterp dut(cfg);
    OutputRecorder rec;
    ASSERT_TRUE(run_golden(dut, frames_of(test::line_tape_text(prog)), 1, kMaxCycles, rec).done);
    EXPECT_EQ(rec.busy_cycles, ceil_div(cfg.feed_modulus, f)) << "F" << f;
    EXPECT_FALSE(rec.starts.at(0).saturated);
    EXPECT_TRUE(check_line_program(prog, rec));
  }
}

TEST(GoldenInterp, SaturatedBlockTakesTwoToTheKPlusOneClocksAndSaysSo) {
  const InterpConfig cfg = parallel_at(1e6);
  const std::vector<LineBlock> prog = {{7, 1000, 300, 4000000000ull}};  // F << 10 >= M
  GoldenInterp dut(cfg);
  OutputRecorder rec;
  ASSERT_TRUE(run_golden(dut, frames_of(test::line_tape_text(prog)), 1, kMaxCycles, rec).done);
  EXPECT_EQ(rec.busy_cycles, 1025u);
  EXPECT_TRUE(rec.starts.at(0).saturated);
  EXPECT_FALSE(rec.last.feed_saturated);  // only while the block plays
  EXPECT_TRUE(check_line_program(prog, rec));
}

TEST(GoldenInterp, ZeroMoveIsADwellOfOneOverF) {
  InterpConfig cfg;
  cfg.feed_modulus = InterpConfig::feed_modulus_for(1000.0, 3);
  const std::vector<LineBlock> prog = {{1, 0, 0, 60000}};  // 1/60 min at 1 kHz = 1000 clocks
  GoldenInterp dut(cfg);
  OutputRecorder rec;
  ASSERT_TRUE(run_golden(dut, frames_of(test::line_tape_text(prog)), 1, kMaxCycles, rec).done);
  EXPECT_EQ(rec.busy_cycles, 1000u);
  EXPECT_TRUE(rec.pulses.empty());
}

// Handshake and latency (docs 3.1, 3.3, 4): one frame per clock into the input register,
// processed one edge later; after the LF of a motion block ready drops while a frame waits
// behind the block being prepared and held; a line's preparation takes k + 2 edges (S = 0
// + F, then doubled k times), and the block loads k + 5 edges after its LF was taken.
TEST(GoldenInterp, HandshakeAndBlockLatency) {
  const std::string text = "%\nN1 G01 X0.002 F100.000\nM02\n%\n";
  const size_t lf = text.find('\n', text.find("N1"));
  GoldenInterp dut(parallel_at(1e6));
  FrameSource source(frames_of(text), 1);
  std::vector<bool> ready{dut.outputs().frame_ready}, busy{false};
  std::vector<uint64_t> taken{0};
  while (!dut.outputs().done && dut.cycle() < kMaxCycles) {
    const bool r = dut.outputs().frame_ready;
    dut.tick(source.inputs());
    source.clock(r);
    ready.push_back(dut.outputs().frame_ready);
    busy.push_back(dut.outputs().busy);
    taken.push_back(source.frames_taken());
  }
  ASSERT_TRUE(dut.outputs().done);
  const size_t k = 2;  // bit length of |X| = 2 BLU
  // Frame i is taken at edge i + 1 up to the frame after the LF (taken at edge lf + 2).
  for (size_t i = 0; i <= lf + 1; ++i) EXPECT_EQ(taken[i + 1], i + 1);
  EXPECT_TRUE(ready[lf + 1]);
  // LF processed at lf + 2: PREPARE, then HOLD at lf + k + 4, with a frame waiting.
  for (size_t e = lf + 2; e <= lf + k + 4; ++e) EXPECT_FALSE(ready[e]) << e;
  EXPECT_TRUE(ready[lf + k + 5]);  // handed to the buffer at lf + k + 5
  EXPECT_EQ(taken[lf + k + 5], lf + 2);
  EXPECT_EQ(taken[lf + k + 6], lf + 3);
  EXPECT_FALSE(busy[lf + k + 5]);
  // LF taken at e, processed e+1, prepared e+2 .. e+k+3, buffer e+k+4, load e+k+5.
  EXPECT_TRUE(busy[lf + k + 6]);
}

TEST(GoldenInterp, BlocksFollowWithoutGapsWhenTheReaderIsFast) {
  InterpConfig cfg;
  cfg.feed_modulus = InterpConfig::feed_modulus_for(1000.0, 3);
  const std::vector<LineBlock> prog = {{1, 5, 1, 6000}, {2, -3, 4, 7000}, {3, 0, -9, 8000}};
  GoldenInterp dut(cfg);
  OutputRecorder rec;
  ASSERT_TRUE(run_golden(dut, frames_of(test::line_tape_text(prog)), 1, kMaxCycles, rec).done);
  ASSERT_EQ(rec.starts.size(), 3u);
  EXPECT_EQ(rec.starts[1].cycle - rec.starts[0].cycle, ceil_div(cfg.feed_modulus, 6000));
  EXPECT_EQ(rec.starts[2].cycle - rec.starts[1].cycle, ceil_div(cfg.feed_modulus, 7000));
  EXPECT_EQ(rec.busy_cycles, rec.cycles - rec.starts[0].cycle - 1);  // busy until the end
  EXPECT_TRUE(check_line_program(prog, rec));
}

TEST(GoldenInterp, SlowReaderLeavesObservableGaps) {
  const InterpConfig cfg = parallel_at(1000.0);
  const std::vector<LineBlock> prog = {{1, 4, 1, 600000000}, {2, 3, -4, 600000000}};
  const std::string text = test::line_tape_text(prog);
  const size_t lf2 = text.find('\n', text.find("N2"));
  GoldenInterp dut(cfg);
  FrameSource source(frames_of(text), 50);
  OutputRecorder rec;
  uint64_t lf2_taken = 0, gap = 0;
  while (!dut.outputs().done && dut.cycle() < kMaxCycles) {
    const bool r = dut.outputs().frame_ready;
    dut.tick(source.inputs());
    source.clock(r);
    if (source.frames_taken() == lf2 + 1 && lf2_taken == 0) lf2_taken = dut.cycle();
    rec.observe(dut.cycle(), dut.outputs());
    if (rec.starts.size() == 1 && !dut.outputs().busy) ++gap;
  }
  ASSERT_EQ(rec.starts.size(), 2u);
  EXPECT_GT(gap, 0u);
  const uint64_t k = 3;  // N2's: bit length of max(|3|, |-4|)
  EXPECT_EQ(rec.starts[1].cycle, lf2_taken + k + 5);  // see HandshakeAndBlockLatency
  EXPECT_TRUE(check_line_program(prog, rec));
}

TEST(GoldenInterp, BlockWithoutNCarriesThePreviousN) {
  const std::string text = "%\nN7 G01 X0.001 F1000.000\nY0.002\nM02\n%\n";
  GoldenInterp dut(interp_config(1e3));
  OutputRecorder rec;
  ASSERT_TRUE(run_golden(dut, frames_of(text), 1, kMaxCycles, rec).done);
  ASSERT_EQ(rec.pulses.size(), 3u);
  for (const auto& p : rec.pulses) EXPECT_EQ(p.block, 7u);
  EXPECT_EQ(rec.last.pos_x, 1);
  EXPECT_EQ(rec.last.pos_y, 2);
}

TEST(GoldenInterp, LeaderCommentsSpacesAndSignsAreAccepted) {
  const std::string text =
      std::string("\0\0\0", 3) + "%\r\n(setup)\nG17 G21 G91 G93 (xy mm incremental)\n"
      "N1 G1 X+0.003 Y-0.00 2 F1000.000\nN2 X-0.000\nM30\n%\n\0\0";
  GoldenInterp dut(interp_config(1e3));
  OutputRecorder rec;
  const InterpOutputs out = run_golden(dut, frames_of(text), 1, kMaxCycles, rec);
  ASSERT_TRUE(out.done) << "error " << int(out.error_code) << " at " << out.error_offset;
  EXPECT_TRUE(check_line_program({{1, 3, -2, 1000000}, {2, 0, 0, 1000000}}, rec));
}

using test::BadTape;

class GoldenBadTape : public ::testing::TestWithParam<BadTape> {};

TEST_P(GoldenBadTape, StopsAtTheBlockBoundaryWithBlockAndOffset) {
  const BadTape& bad = GetParam();
  GoldenInterp dut(interp_config(1e3));
  OutputRecorder rec;
  const InterpOutputs out = run_golden(dut, bad.frames(), 1, kMaxCycles, rec);
  ASSERT_TRUE(out.error);
  EXPECT_FALSE(out.done);
  EXPECT_EQ(out.error_code, static_cast<uint8_t>(bad.code));
  EXPECT_EQ(out.error_block, bad.block);
  EXPECT_EQ(out.error_offset, bad.offset);
  EXPECT_FALSE(out.frame_ready);
  EXPECT_FALSE(out.busy);
  EXPECT_TRUE(check_line_program(bad.good, rec));
}

INSTANTIATE_TEST_SUITE_P(Tapes, GoldenBadTape, ::testing::ValuesIn(test::bad_tapes()),
                         [](const auto& info) { return std::string(info.param.name); });

TEST(GoldenInterp, ErrorRisesTwoClocksAfterTheLastGoodBlockFinishes) {
  // The bad block is found while N10 plays (fast reader, slow block).
  const std::string text = "%\nN10 G01 X0.004 F60000.000\nN20 Q\n";
  GoldenInterp dut(interp_config(1e3));
  OutputRecorder rec;
  uint64_t last_busy = 0, error_cycle = 0;
  FrameSource source(frames_of(text), 1);
  while (!dut.outputs().error && dut.cycle() < kMaxCycles) {
    const bool r = dut.outputs().frame_ready;
    dut.tick(source.inputs());
    source.clock(r);
    if (dut.outputs().busy) last_busy = dut.cycle();
    if (dut.outputs().error) error_cycle = dut.cycle();
    EXPECT_EQ(dut.outputs().error_code, dut.outputs().error ? 2 : 0);
  }
  EXPECT_EQ(error_cycle, last_busy + 2);
  EXPECT_EQ(dut.outputs().pos_x, 4);
}

// Fault hook (docs section 9).
struct FaultRun {
  OutputRecorder rec;
  std::vector<InterpOutputs> outs;
};

FaultRun run_with_fault(const std::string& text, const GoldenInterp::Fault& fault) {
  GoldenInterp dut(interp_config(1e3));
  dut.inject(fault);
  FaultRun run;
  FrameSource source(frames_of(text), 1);
  run.outs.push_back(dut.outputs());
  while (!dut.outputs().done && !dut.outputs().error && dut.cycle() < kMaxCycles) {
    const bool r = dut.outputs().frame_ready;
    dut.tick(source.inputs());
    source.clock(r);
    run.outs.push_back(dut.outputs());
    run.rec.observe(dut.cycle(), dut.outputs());
  }
  return run;
}

const std::string kFaultTape = "%\nN1 G01 X0.010 Y0.004 F1000.000\nN2 X0.003 Y-0.001\nM02\n%\n";

size_t first_difference(const FaultRun& a, const FaultRun& b) {
  for (size_t i = 0; i < a.outs.size() && i < b.outs.size(); ++i)
    if (a.outs[i] != b.outs[i]) return i;
  return std::min(a.outs.size(), b.outs.size());
}

TEST(GoldenFault, LostPulseSuppressesTheFirstPulseAtOrAfterTheCycle) {
  const FaultRun clean = run_with_fault(kFaultTape, {});
  uint64_t second_x = 0;
  int seen = 0;
  for (const auto& p : clean.rec.pulses)
    if (p.axis == 0 && ++seen == 2) second_x = p.cycle;
  const FaultRun faulty =
      run_with_fault(kFaultTape, {GoldenInterp::Fault::kLostPulse, second_x - 3, 0});
  EXPECT_EQ(first_difference(clean, faulty), second_x);
  EXPECT_FALSE(faulty.outs[second_x].step_x);
  EXPECT_EQ(faulty.rec.last.pos_x, clean.rec.last.pos_x - 1);
  EXPECT_EQ(faulty.rec.last.pos_y, clean.rec.last.pos_y);
}

TEST(GoldenFault, StuckStepHoldsTheStepForTheRestOfTheBlock) {
  const FaultRun clean = run_with_fault(kFaultTape, {});
  const uint64_t start1 = clean.rec.starts.at(0).cycle, start2 = clean.rec.starts.at(1).cycle;
  const uint64_t c = start1 + 5;
  const FaultRun faulty = run_with_fault(kFaultTape, {GoldenInterp::Fault::kStuckStep, c, 1});
  for (uint64_t i = c; i < start2; ++i) EXPECT_TRUE(faulty.outs[i].step_y) << i;
  EXPECT_FALSE(faulty.outs[start2].step_y && !clean.outs[start2].step_y);
  EXPECT_EQ(first_difference(clean, faulty), c);
  // The position counts what the step output shows.
  EXPECT_EQ(faulty.outs[start2 - 1].pos_y, static_cast<int64_t>(start2 - c) +
                                               clean.outs[c - 1].pos_y);
}

TEST(GoldenFault, AccumulatorOffByOneMovesAPulseEarlierAndTheCountersKeepTheCount) {
  // k = 2, inc 3, acc from 2: carries at iterations 1, 2 and 4; from 3 (the fault at the
  // load edge): 1, 2 and 3, and the 4th iteration's carry never comes (the block still
  // ends after its 4 iterations with 3 pulses: the pulse counter caps the count).
  const std::string text = "%\nN1 G01 X0.003 F1000.000\nM02\n%\n";
  const FaultRun clean = run_with_fault(text, {});
  const uint64_t start = clean.rec.starts.at(0).cycle;
  const FaultRun faulty =
      run_with_fault(text, {GoldenInterp::Fault::kAccumulatorOffByOne, start, 0});
  EXPECT_EQ(clean.rec.last.pos_x, 3);
  EXPECT_EQ(faulty.rec.last.pos_x, 3);
  EXPECT_GT(first_difference(clean, faulty), start);
}

TEST(GoldenFault, WrongDirectionInvertsDirAndCountsBackwardsForTheBlock) {
  const FaultRun clean = run_with_fault(kFaultTape, {});
  const uint64_t start2 = clean.rec.starts.at(1).cycle;
  const uint64_t c = clean.rec.starts.at(0).cycle + 1;
  const FaultRun faulty =
      run_with_fault(kFaultTape, {GoldenInterp::Fault::kWrongDirection, c, 0});
  EXPECT_EQ(first_difference(clean, faulty), c);
  for (uint64_t i = c; i < start2; ++i) EXPECT_FALSE(faulty.outs[i].dir_x) << i;
  EXPECT_TRUE(faulty.outs[start2].dir_x);  // the next block is normal again
  EXPECT_EQ(faulty.rec.last.pos_x, -10 + 3);
}

TEST(GoldenFault, FaultBeforeAnyBlockWaitsForABlock) {
  const FaultRun clean = run_with_fault(kFaultTape, {});
  const FaultRun faulty = run_with_fault(kFaultTape, {GoldenInterp::Fault::kWrongDirection, 1, 1});
  EXPECT_EQ(first_difference(clean, faulty), clean.rec.starts.at(0).cycle);
}

TEST(GoldenRandom, LineTapesPlayExactlyWithinTheBound) {
  std::mt19937_64 rng(20240601);
  for (int t = 0; t < 100; ++t) {
    const InterpConfig cfg = interp_config(1e3);
    const std::vector<LineBlock> prog = test::random_line_program(rng, 16, cfg.feed_modulus);
    GoldenInterp dut(cfg);
    OutputRecorder rec;
    const InterpOutputs out =
        run_golden(dut, frames_of(test::line_tape_text(prog)), 1, kMaxCycles, rec);
    ASSERT_TRUE(out.done) << "tape " << t;
    ASSERT_TRUE(check_line_program(prog, rec)) << "tape " << t;
  }
}

}  // namespace
}  // namespace ncinterp
