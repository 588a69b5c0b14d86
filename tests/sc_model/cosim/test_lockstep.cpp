// Lock-step cosim tests: RTL and golden model equal on every clock for random line tapes
// and bad tapes, with exact pulses and the L1 path bound; the scoreboard reports an
// injected golden-model fault at the right cycle and block; the VCD window is written.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <random>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "interp_test_support.h"
#include "lockstep.h"
#include "rtl_vcd.h"

namespace ncinterp {
namespace {

using cosim::Options;
using cosim::Result;
using test::check_line_program;
using test::frames_of;
using test::LineBlock;
using test::OutputRecorder;

Options fast_options() {
  Options o;
  o.config = interp_config(1e3);  // 1 kHz: high feeds saturate, runs stay short
  o.cycles_per_frame = 1;
  o.max_cycles = 50'000'000;
  return o;
}

Result run(const std::vector<uint8_t>& frames, const Options& o, OutputRecorder& rec) {
  return cosim::run_lockstep(frames, o, [&](uint64_t c, const InterpOutputs& out) {
    rec.observe(c, out);
  });
}

// Random line tapes in shards, so ctest can run them in parallel.
class CosimRandom : public ::testing::TestWithParam<int> {};

TEST_P(CosimRandom, RtlEqualsGoldenAndPulsesAreExactWithinTheBound) {
  const int shard = GetParam();
  std::mt19937_64 rng(7919 + shard);
  const Options o = fast_options();
  for (int t = 0; t < 50; ++t) {
    const std::vector<LineBlock> prog = test::random_line_program(rng, 16, o.config.feed_modulus);
    OutputRecorder rec;
    const Result r = run(frames_of(test::line_tape_text(prog)), o, rec);
    ASSERT_FALSE(r.mismatch) << "shard " << shard << " tape " << t << ": "
                             << cosim::describe(*r.mismatch);
    ASSERT_EQ(r.end, Result::End::kDone) << "shard " << shard << " tape " << t;
    ASSERT_TRUE(check_line_program(prog, rec)) << "shard " << shard << " tape " << t;
    ASSERT_EQ(r.stats.blocks, prog.size());
    uint64_t pulses = 0;
    for (const LineBlock& b : prog) pulses += std::llabs(b.dx) + std::llabs(b.dy);
    ASSERT_EQ(r.stats.pulses[0][0] + r.stats.pulses[0][1] + r.stats.pulses[1][0] +
                  r.stats.pulses[1][1],
              pulses);
  }
}

INSTANTIATE_TEST_SUITE_P(Shards, CosimRandom, ::testing::Range(0, 6));

// The same with a 1 MHz clock and realistic feeds: phase-accumulated blocks with long
// idle stretches between iterations, and a slow reader that leaves gaps; in both archs
// (the serial one saturates the first block too: 2P clocks per iteration).
class CosimArch : public ::testing::TestWithParam<Arch> {};

TEST_P(CosimArch, SlowReaderAndRealFeedsStayInLockStep) {
  Options o;
  o.config = interp_config(1e6);
  o.config.arch = GetParam();
  o.cycles_per_frame = 200;
  const std::vector<LineBlock> prog = {{1, 1234, -567, 3000000}, {2, -5, 2, 20000000},
                                       {3, 0, 0, 90000000},      {4, 65535, 65535, 4000000000ull}};
  OutputRecorder rec;
  const Result r = run(frames_of(test::line_tape_text(prog)), o, rec);
  ASSERT_FALSE(r.mismatch) << cosim::describe(*r.mismatch);
  ASSERT_EQ(r.end, Result::End::kDone);
  EXPECT_TRUE(check_line_program(prog, rec));
  EXPECT_GT(r.stats.gap_cycles, 0u);
  EXPECT_EQ(r.stats.saturated_blocks, GetParam() == Arch::kSerial ? 2u : 1u);
}

// A 20 kHz machine (short ramped runs) in the given arch, the reader one frame a clock.
Options at_20khz(Arch arch) {
  Options o;
  o.config = interp_config(20e3);
  o.config.arch = arch;
  o.cycles_per_frame = 1;
  return o;
}

// The same pulses in the same order (at any times).
::testing::AssertionResult same_pulse_order(const OutputRecorder& a, const OutputRecorder& b) {
  if (a.pulses.size() != b.pulses.size())
    return ::testing::AssertionFailure() << a.pulses.size() << " pulses against " << b.pulses.size();
  for (size_t i = 0; i < a.pulses.size(); ++i)
    if (a.pulses[i].axis != b.pulses[i].axis || a.pulses[i].plus != b.pulses[i].plus ||
        a.pulses[i].block != b.pulses[i].block)
      return ::testing::AssertionFailure() << "pulse " << i << " differs";
  return ::testing::AssertionSuccess();
}

// The feed ramp (accel_step > 0): lines and arcs at a 20 kHz clock, every block ramped
// from rest and braked to rest, in lock step on both archs, the same pulses as unramped.
TEST_P(CosimArch, RampedBlocksStayInLockStepWithThePulsesOfUnrampedOnes) {
  std::mt19937_64 rng(3301);
  for (int t = 0; t < 6; ++t) {
    Options o = at_20khz(GetParam());
    const std::vector<LineBlock> prog = test::random_line_program(rng, 12, o.config.feed_modulus);
    const std::vector<uint8_t> frames = frames_of(test::line_tape_text(prog));
    OutputRecorder plain_rec;
    const Result plain = run(frames, o, plain_rec);
    o.config.accel_step = InterpConfig::accel_step_for(500, 20e3, 3, o.config.feed_modulus);
    OutputRecorder rec;
    const Result r = run(frames, o, rec);
    ASSERT_FALSE(r.mismatch) << "tape " << t << ": " << cosim::describe(*r.mismatch);
    ASSERT_EQ(r.end, Result::End::kDone) << "tape " << t;
    EXPECT_TRUE(check_line_program(prog, rec)) << "tape " << t;
    EXPECT_TRUE(same_pulse_order(rec, plain_rec)) << "tape " << t;
    EXPECT_GT(rec.cycles, plain_rec.cycles);
  }
  Options o = at_20khz(GetParam());
  o.config.accel_step = InterpConfig::accel_step_for(500, 20e3, 3, o.config.feed_modulus);
  const char* arcs =
      "%\nG17 G21 G91 G93\nN1 G03 X-5.000 Y5.000 I-5.000 J0.000 F120.000\n"
      "N2 G01 X3.000 Y0.250 F400.000\nN3 G02 X2.000 Y-2.000 I0.000 J-2.000 F300.000\n"
      "N4 G00 X-1.000 Y-7.000\nM02\n%\n";
  OutputRecorder rec;
  const Result r = run(frames_of(arcs), o, rec);
  ASSERT_FALSE(r.mismatch) << cosim::describe(*r.mismatch);
  ASSERT_EQ(r.end, Result::End::kDone);
}

// The operator's feed hold and cycle start at random clocks, with and without the ramp:
// lock step on both archs, and the pulses of the run without presses, in the same order.
TEST_P(CosimArch, HoldsAndStartsStayInLockStepAndKeepThePulses) {
  std::mt19937_64 rng(3302);
  for (int t = 0; t < 8; ++t) {
    Options o = at_20khz(GetParam());
    if (t % 2 == 0) o.config.accel_step = InterpConfig::accel_step_for(500, 20e3, 3, o.config.feed_modulus);
    const std::vector<LineBlock> prog = test::random_line_program(rng, 12, o.config.feed_modulus);
    const std::vector<uint8_t> frames = frames_of(test::line_tape_text(prog));
    OutputRecorder plain_rec;
    const Result plain = run(frames, o, plain_rec);
    ASSERT_EQ(plain.end, Result::End::kDone);
    // Presses within the run: each hold followed by a start a little later.
    std::uniform_int_distribution<uint64_t> when(1, plain.cycles), gap(1, 3000);
    for (int k = 0; k < 4; ++k) {
      const uint64_t at = when(rng);
      o.events.push_back({at, OperatorEvent::kHold});
      o.events.push_back({at + gap(rng), OperatorEvent::kStart});
    }
    std::sort(o.events.begin(), o.events.end(),
              [](const OperatorEvent& a, const OperatorEvent& b) { return a.cycle < b.cycle; });
    OutputRecorder rec;
    const Result r = run(frames, o, rec);
    ASSERT_FALSE(r.mismatch) << "tape " << t << ": " << cosim::describe(*r.mismatch);
    ASSERT_EQ(r.end, Result::End::kDone) << "tape " << t;
    EXPECT_TRUE(same_pulse_order(rec, plain_rec)) << "tape " << t;
  }
}

// The feed and rapid overrides at random clocks and levels (0 % to 200 %; 25, 50, 100 % for
// rapids), with holds among them, on a ramped program of lines, arcs and a rapid: lock step
// on both archs, and the pulses of the run without overrides, in the same order. A run at
// 50 % takes longer than at 100 %, one at 200 % less where the blocks are below the cap.
TEST_P(CosimArch, OverridesStayInLockStepAndKeepThePulses) {
  std::mt19937_64 rng(3304);
  Options o = at_20khz(GetParam());
  o.config.accel_step = InterpConfig::accel_step_for(500, 20e3, 3, o.config.feed_modulus);
  const char* tape =
      "%\nG17 G21 G91 G93\nN1 G03 X-5.000 Y5.000 I-5.000 J0.000 F60.000\n"
      "N2 G01 X3.000 Y0.250 F100.000\nN3 G00 X-1.000 Y-7.000\nN4 G01 X-1.500 Y2.250 F80.000\n"
      "N5 G02 X2.000 Y-2.000 I0.000 J-2.000 F90.000\nN6 G00 X2.000 Y1.000\nM02\n%\n";
  const std::vector<uint8_t> frames = frames_of(tape);
  OutputRecorder plain_rec;
  const Result plain = run(frames, o, plain_rec);
  ASSERT_FALSE(plain.mismatch) << cosim::describe(*plain.mismatch);
  ASSERT_EQ(plain.end, Result::End::kDone);
  for (uint16_t level : {uint16_t{64}, uint16_t{256}}) {
    Options at = o;
    at.events = {{1, OperatorEvent::kFeedOverride, level}};
    OutputRecorder rec;
    const Result r = run(frames, at, rec);
    ASSERT_FALSE(r.mismatch) << level << ": " << cosim::describe(*r.mismatch);
    ASSERT_EQ(r.end, Result::End::kDone) << level;
    EXPECT_TRUE(same_pulse_order(rec, plain_rec)) << level;
    if (level < kOverrideOne) EXPECT_GT(r.cycles, plain.cycles + plain.cycles / 2);
    // The serial arch plays these feeds at its cap (one iteration per serial iteration)
    // already: 200 % cannot make it faster, and each of the 6 blocks waits for the
    // override's product (kOverrideWidth clocks) before it climbs.
    else if (GetParam() == Arch::kParallel) EXPECT_LT(r.cycles, plain.cycles);
    else EXPECT_LE(r.cycles, plain.cycles + 6 * kOverrideWidth);
  }
  const uint16_t rapid_levels[] = {32, 64, 128};
  for (int t = 0; t < 6; ++t) {
    Options at = o;
    std::uniform_int_distribution<uint64_t> when(1, plain.cycles);
    std::uniform_int_distribution<int> level(0, 2 * kOverrideOne);
    for (int k = 0; k < 6; ++k) {
      at.events.push_back({when(rng), OperatorEvent::kFeedOverride, static_cast<uint16_t>(level(rng))});
      at.events.push_back({when(rng), OperatorEvent::kRapidOverride, rapid_levels[rng() % 3]});
    }
    if (t % 2) at.events.push_back({when(rng), OperatorEvent::kHold});
    if (t % 2) at.events.push_back({at.events.back().cycle + 4000, OperatorEvent::kStart});
    if (t % 3 == 0) at.events.push_back({when(rng), OperatorEvent::kFeedOverride, 0});
    // The last word is the feed override's: not 0, so that the program ends.
    at.events.push_back({plain.cycles + 1, OperatorEvent::kFeedOverride, static_cast<uint16_t>(64 + level(rng) / 2)});
    sort_by_clock(at.events);
    OutputRecorder rec;
    const Result r = run(frames, at, rec);
    ASSERT_FALSE(r.mismatch) << "run " << t << ": " << cosim::describe(*r.mismatch);
    ASSERT_EQ(r.end, Result::End::kDone) << "run " << t << ": " << events_text(at.events, 20e3);
    EXPECT_TRUE(same_pulse_order(rec, plain_rec)) << "run " << t;
  }
}

// The M words (M03 and M05 on the tool output, M00 and M01 pausing until cycle start):
// lock step on both archs, with and without the ramp, with the optional stop switch on and
// off and cycle start pressed at random clocks. The pulses are those of the tape without
// its M words; every pulse of a block between M03 and M05 has the tool on and every other
// the tool off; the program pauses at each M00 (and M01 with the switch on), emits no pulse
// while paused, and goes on at the next press. Without a press the run ends paused.
TEST_P(CosimArch, MWordsStayInLockStepAndKeepThePulses) {
  std::mt19937_64 rng(3305);
  const std::string head = "%\nG17 G21 G91 G93\nN1 G00 X2.000 Y1.000\n";
  const std::string tail = "N10 G00 X-4.000 Y-3.000\nM02\n%\n";
  const std::string m_tape = head +
      "N2 M03\nN3 G01 X3.000 Y0.000 F300.000\nN4 G03 X-2.000 Y2.000 I-2.000 J0.000 F120.000\n"
      "N5 G01 X-1.000 Y-1.000 F200.000 M05\nN6 M00\nN7 G01 X2.000 Y1.000 F400.000 M03\n"
      "N8 M01\nN9 G01 X0.000 Y0.000 F400.000 M05\n" + tail;
  const std::string plain_tape = head +
      "N3 G01 X3.000 Y0.000 F300.000\nN4 G03 X-2.000 Y2.000 I-2.000 J0.000 F120.000\n"
      "N5 G01 X-1.000 Y-1.000 F200.000\nN7 G01 X2.000 Y1.000 F400.000\n" + tail;
  const std::set<uint32_t> tool_blocks = {3, 4, 5, 7};  // M03 at N2's load, M05 after N5 ...
  for (const bool ramped : {false, true}) {
    Options o = at_20khz(GetParam());
    if (ramped) o.config.accel_step = InterpConfig::accel_step_for(500, 20e3, 3, o.config.feed_modulus);
    OutputRecorder plain_rec;
    const Result plain = run(frames_of(plain_tape), o, plain_rec);
    ASSERT_EQ(plain.end, Result::End::kDone);
    for (int t = 0; t < 4; ++t) {
      Options at = o;
      const bool optional = t % 2 == 1;
      if (optional) at.events.push_back({1, OperatorEvent::kOptionalStop, 1});
      std::uniform_int_distribution<uint64_t> gap(1, plain.cycles / 4);
      for (uint64_t c = gap(rng); c < 4 * plain.cycles; c += gap(rng))
        at.events.push_back({c, OperatorEvent::kStart});
      OutputRecorder rec;
      int pauses = 0;
      bool was_paused = false, pulse_while_paused = false, tool_wrong = false;
      const Result r = cosim::run_lockstep(frames_of(m_tape), at, [&](uint64_t c, const InterpOutputs& out) {
        rec.observe(c, out);
        pauses += out.paused && !was_paused;
        was_paused = out.paused;
        if (out.step_x || out.step_y) {
          pulse_while_paused |= out.paused;
          tool_wrong |= out.tool != (tool_blocks.count(out.block_n) > 0);
        }
      });
      const std::string run = std::string(ramped ? "ramped" : "unramped") + " run " + std::to_string(t);
      ASSERT_FALSE(r.mismatch) << run << ": " << cosim::describe(*r.mismatch);
      ASSERT_EQ(r.end, Result::End::kDone) << run;
      EXPECT_TRUE(same_pulse_order(rec, plain_rec)) << run;
      EXPECT_EQ(pauses, optional ? 2 : 1) << run;
      EXPECT_FALSE(pulse_while_paused) << run;
      EXPECT_FALSE(tool_wrong) << run;
      EXPECT_FALSE(r.last.tool) << run;  // off after N9's M05, and at the end of the program
      EXPECT_EQ(r.last.pos_x, 0);
      EXPECT_EQ(r.last.pos_y, 0);
    }
    const Result unpressed = run(frames_of(m_tape), o, *std::make_unique<OutputRecorder>());
    ASSERT_FALSE(unpressed.mismatch) << cosim::describe(*unpressed.mismatch);
    EXPECT_EQ(unpressed.end, Result::End::kPaused);
    EXPECT_EQ(unpressed.last.block_n, 6u);
    EXPECT_TRUE(unpressed.last.paused);
  }
}

// E-stop and the limits at random clocks, after random holds, with and without the ramp:
// lock step on both archs; the run ends at the stop's clock in the error with the stop's
// code, naming the block playing; its pulses are the first ones of the run without the
// stop, in order, none after that clock, and the position counters add them up.
TEST_P(CosimArch, StopsEndInLockStepAtTheirClockWithAPrefixOfThePulses) {
  std::mt19937_64 rng(3303);
  const OperatorEvent::Kind kinds[] = {OperatorEvent::kEStop, OperatorEvent::kLimitX, OperatorEvent::kLimitY};
  int mid_block = 0;
  for (int t = 0; t < 12; ++t) {
    Options o = at_20khz(GetParam());
    if (t % 2 == 0) o.config.accel_step = InterpConfig::accel_step_for(500, 20e3, 3, o.config.feed_modulus);
    const std::vector<LineBlock> prog = test::random_line_program(rng, 12, o.config.feed_modulus);
    const std::vector<uint8_t> frames = frames_of(test::line_tape_text(prog));
    if (t % 3 == 0) o.events.push_back({std::uniform_int_distribution<uint64_t>(1, 2000)(rng), OperatorEvent::kHold});
    if (t % 3 == 0) o.events.push_back({o.events.back().cycle + 500, OperatorEvent::kStart});
    OutputRecorder plain_rec;
    const Result plain = run(frames, o, plain_rec);
    ASSERT_EQ(plain.end, Result::End::kDone);
    const uint64_t at = std::uniform_int_distribution<uint64_t>(1, plain.cycles)(rng);
    const OperatorEvent::Kind kind = kinds[t % 3];
    o.events.push_back({at, kind});
    sort_by_clock(o.events);
    OutputRecorder rec;
    const Result r = run(frames, o, rec);
    ASSERT_FALSE(r.mismatch) << "tape " << t << ": " << cosim::describe(*r.mismatch);
    ASSERT_EQ(r.end, Result::End::kTapeError) << "tape " << t;
    EXPECT_EQ(r.cycles, at) << "tape " << t;
    EXPECT_EQ(r.last.error_code, static_cast<uint8_t>(stop_error(kind))) << "tape " << t;
    EXPECT_EQ(r.last.error_block, r.last.block_n) << "tape " << t;
    EXPECT_EQ(r.last.error_offset, 0u) << "tape " << t;
    mid_block += r.last.busy;
    ASSERT_LE(rec.pulses.size(), plain_rec.pulses.size()) << "tape " << t;
    int64_t x = 0, y = 0;
    for (size_t i = 0; i < rec.pulses.size(); ++i) {
      const auto& p = rec.pulses[i];
      const auto& q = plain_rec.pulses[i];
      ASSERT_TRUE(p.axis == q.axis && p.plus == q.plus && p.block == q.block) << "tape " << t << " pulse " << i;
      EXPECT_LE(p.cycle, at) << "tape " << t;
      (p.axis == 0 ? x : y) += p.plus ? 1 : -1;
    }
    EXPECT_EQ(r.last.pos_x, x) << "tape " << t;
    EXPECT_EQ(r.last.pos_y, y) << "tape " << t;
  }
  EXPECT_GE(mid_block, 4);  // most stops land in a block, not between blocks
}

INSTANTIATE_TEST_SUITE_P(Archs, CosimArch, ::testing::Values(Arch::kSerial, Arch::kParallel),
                         [](const ::testing::TestParamInfo<Arch>& i) { return arch_name(i.param); });

class CosimBadTape : public ::testing::TestWithParam<test::BadTape> {};

TEST_P(CosimBadTape, BothEnginesStopAtTheBlockBoundary) {
  const test::BadTape& bad = GetParam();
  OutputRecorder rec;
  const Result r = run(bad.frames(), fast_options(), rec);
  ASSERT_FALSE(r.mismatch) << cosim::describe(*r.mismatch);
  ASSERT_EQ(r.end, Result::End::kTapeError);
  EXPECT_EQ(r.last.error_code, static_cast<uint8_t>(bad.code));
  EXPECT_EQ(r.last.error_block, bad.block);
  EXPECT_EQ(r.last.error_offset, bad.offset);
  EXPECT_TRUE(check_line_program(bad.good, rec));
}

INSTANTIATE_TEST_SUITE_P(Tapes, CosimBadTape, ::testing::ValuesIn(test::bad_tapes()),
                         [](const auto& info) { return std::string(info.param.name); });

// The scoreboard can fail: a one-cycle fault in the golden model is reported at the cycle
// and block where it first shows, with the cycles matched before it.
const std::vector<LineBlock> kFaultProgram = {{11, 40, 25, 2000000}, {12, -30, 10, 2000000}};

TEST(CosimScoreboard, ReportsAnInjectedFaultAtItsCycleAndBlock) {
  const std::vector<uint8_t> frames = frames_of(test::line_tape_text(kFaultProgram));
  OutputRecorder clean;
  ASSERT_EQ(run(frames, fast_options(), clean).end, Result::End::kDone);
  // A cycle inside block 12 with no pulse on X, and the first X pulse after it.
  uint64_t start12 = 0;
  for (const auto& s : clean.starts)
    if (s.block == 12) start12 = s.cycle;
  ASSERT_GT(start12, 0u);
  std::set<uint64_t> x_pulses;
  for (const auto& p : clean.pulses)
    if (p.axis == 0) x_pulses.insert(p.cycle);
  uint64_t c = start12 + 3;
  while (x_pulses.count(c)) ++c;
  const auto next = x_pulses.upper_bound(c);
  ASSERT_NE(next, x_pulses.end());
  const uint64_t next_x = *next;

  struct Case {
    GoldenInterp::Fault::Kind kind;
    uint64_t cycle;
    const char* signal;
    int64_t expected, actual;
  };
  const Case cases[] = {
      {GoldenInterp::Fault::kLostPulse, c, "step_x_o", 0, 1},
      {GoldenInterp::Fault::kStuckStep, c, "step_x_o", 1, 0},
      {GoldenInterp::Fault::kWrongDirection, c, "dir_x_o", 1, 0},  // block 12 moves -X
  };
  for (const Case& k : cases) {
    Options o = fast_options();
    o.fault = {k.kind, c, 0};
    const Result r = cosim::run_lockstep(frames, o);
    ASSERT_TRUE(r.mismatch) << "fault kind " << k.kind << " not reported";
    const uint64_t want = k.kind == GoldenInterp::Fault::kLostPulse ? next_x : c;
    EXPECT_EQ(r.end, Result::End::kMismatch);
    EXPECT_EQ(r.mismatch->cycle, want) << cosim::describe(*r.mismatch);
    EXPECT_EQ(r.mismatch->block, 12u);
    EXPECT_EQ(r.mismatch->signal, k.signal);
    EXPECT_EQ(r.mismatch->expected, k.expected);
    EXPECT_EQ(r.mismatch->actual, k.actual);
    EXPECT_EQ(r.mismatch->cycles_matched, want - 1);
    EXPECT_EQ(r.cycles, want);
  }
}

TEST(CosimScoreboard, AccumulatorFaultShowsUpLaterInThePulses) {
  // dx = 3 BLU (k = 2): one more LSB at the load moves the third pulse one iteration earlier.
  const std::vector<uint8_t> frames = frames_of(test::line_tape_text({{5, 3, 0, 2000000}}));
  OutputRecorder clean;
  ASSERT_EQ(run(frames, fast_options(), clean).end, Result::End::kDone);
  Options o = fast_options();
  o.fault = {GoldenInterp::Fault::kAccumulatorOffByOne, clean.starts.at(0).cycle, 0};
  const Result r = cosim::run_lockstep(frames, o);
  ASSERT_TRUE(r.mismatch);
  EXPECT_GT(r.mismatch->cycle, clean.starts.at(0).cycle);
  EXPECT_EQ(r.mismatch->block, 5u);
}

TEST(CosimScoreboard, StopsAtTheCycleLimit) {
  Options o = fast_options();
  o.max_cycles = 100;
  const Result r = cosim::run_lockstep(frames_of(test::line_tape_text(kFaultProgram)), o);
  EXPECT_EQ(r.end, Result::End::kCycleLimit);
  EXPECT_EQ(r.cycles, 100u);
  EXPECT_FALSE(r.mismatch);
}

TEST(CosimVcd, WritesTheRequestedWindowOfTheRtl) {
  const std::string path = ::testing::TempDir() + "cosim_window.vcd";
  std::remove(path.c_str());
  const std::vector<uint8_t> frames = frames_of(test::line_tape_text(kFaultProgram));
  cosim::write_rtl_vcd(frames, fast_options(), 1e3, 40, 60, path);
  std::ifstream in(path);
  ASSERT_TRUE(in.good());
  std::stringstream text;
  text << in.rdbuf();
  const std::string vcd = text.str();
  // The full path of the port, as the system model's VCDs name it (docs/waves.md).
  std::vector<std::string> scopes;
  std::set<std::string> step_x_paths;
  std::istringstream lines(vcd);
  for (std::string line; std::getline(lines, line);) {
    std::istringstream words(line);
    std::string w, kind, name;
    words >> w;
    if (w == "$scope") {
      words >> kind >> name;
      scopes.push_back(name);
    } else if (w == "$upscope") {
      scopes.pop_back();
    } else if (w == "$var" && line.find(" step_x_o ") != std::string::npos) {
      std::string path;
      for (const std::string& sc : scopes) path += sc + ".";
      step_x_paths.insert(path + "step_x_o");
    }
  }
  EXPECT_EQ(step_x_paths.count("SystemC.interp.interp_top.step_x_o"), 1u);
  // 1 kHz: edge c at (c + 1) ms, clk low half a period before (docs/waves.md).
  EXPECT_NE(vcd.find("#40500000000"), std::string::npos);  // clk low before edge 40
  EXPECT_EQ(vcd.find("#39500000000"), std::string::npos);
  EXPECT_NE(vcd.find("#61000000000"), std::string::npos);  // edge 60
  EXPECT_EQ(vcd.find("#62000000000"), std::string::npos);
  for (const auto& entry : std::filesystem::directory_iterator(::testing::TempDir()))
    EXPECT_EQ(entry.path().filename().string().rfind(".cosim_window.vcd", 0), std::string::npos)
        << "temporary left behind: " << entry.path();
  std::remove(path.c_str());
}

}  // namespace
}  // namespace ncinterp
