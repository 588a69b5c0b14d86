// Unit tests of the golden model's feed ramp (accel_step > 0, docs/motion-control.md):
// a ramp changes only when the DDA iterates, so every block emits exactly the pulses it
// emits without ramps, in the same order; every block starts and ends at rest; the rate
// moves by at most one step per clock; the axes' accelerations measured from the pulse
// times stay within the limit the step stands for.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <string>
#include <vector>

#include "frame_source.h"
#include "interp_top.h"

#include "interp_test_support.h"

namespace ncinterp {
namespace {

using test::frames_of;
using test::LineBlock;
using test::OutputRecorder;

constexpr uint64_t kMaxCycles = 20'000'000;  // the longest run here takes 3 M clocks

// A slow clock keeps the runs short; the ramp's arithmetic is the same at any clock.
constexpr double kClockHz = 20e3;

InterpConfig ramped(Arch arch, double accel_mm_s2) {
  InterpConfig cfg = interp_config(kClockHz);
  cfg.arch = arch;
  cfg.accel_step = InterpConfig::accel_step_for(accel_mm_s2, kClockHz, cfg.frac_digits,
                                                cfg.feed_modulus);
  return cfg;
}

// A run that records the rate at every clock beside the outputs.
struct RampRun {
  OutputRecorder rec;
  std::vector<uint64_t> rate;   // u after each clock
  std::vector<bool> loaded;     // a block loaded at this clock
  InterpOutputs out;
};

RampRun play(const InterpConfig& cfg, const std::string& tape) {
  RampRun r;
  GoldenInterp dut(cfg);
  const std::vector<uint8_t> frames = frames_of(tape);
  size_t next = 0;
  InterpInputs in;
  uint64_t loads = 0;
  for (uint64_t c = 1; c <= kMaxCycles; ++c) {
    in.frame_valid = next < frames.size();
    in.frame = in.frame_valid ? frames[next] : 0;
    in.tape_end = !in.frame_valid;
    if (in.frame_valid && dut.outputs().frame_ready) ++next;
    dut.tick(in);
    r.rec.observe(dut.cycle(), dut.outputs());
    r.rate.push_back(dut.rate());
    r.loaded.push_back(dut.blocks_loaded() != loads);
    loads = dut.blocks_loaded();
    if (dut.outputs().done || dut.outputs().error) break;
  }
  r.out = dut.outputs();
  return r;
}

const char* kArcTape =
    "%\nG17 G21 G91 G93\n"
    "N1 G03 X-5.000 Y5.000 I-5.000 J0.000 F120.000\n"
    "N2 G01 X3.000 Y0.250 F400.000\n"
    "N3 G02 X2.000 Y-2.000 I0.000 J-2.000 F300.000\n"
    "N4 G01 X0.001 Y0.000 F5000.000\n"
    "N5 G01 X-0.500 Y-3.000 F90.000\n"
    "M02\n%\n";

// The pulses as a sequence, without their times.
struct PulseKey {
  uint32_t block;
  int axis;
  bool plus;
  bool operator==(const PulseKey& o) const {
    return block == o.block && axis == o.axis && plus == o.plus;
  }
};
std::vector<PulseKey> keys(const OutputRecorder& rec) {
  std::vector<PulseKey> k;
  for (const auto& p : rec.pulses) k.push_back({p.block, p.axis, p.plus});
  return k;
}

std::vector<std::string> tapes() {
  std::mt19937_64 rng(33);
  std::vector<std::string> t{kArcTape};
  for (int i = 0; i < 6; ++i) {
    const InterpConfig cfg = interp_config(kClockHz);
    std::vector<LineBlock> prog = test::random_line_program(rng, 12, cfg.feed_modulus);
    t.push_back(test::line_tape_text(prog));
  }
  return t;
}

class GoldenRamp : public ::testing::TestWithParam<Arch> {};

TEST_P(GoldenRamp, EveryBlockEmitsTheSamePulsesInTheSameOrderAsWithoutRamps) {
  for (const std::string& tape : tapes()) {
    const RampRun plain = play(ramped(GetParam(), 0), tape);
    const RampRun ramp = play(ramped(GetParam(), 500), tape);
    ASSERT_TRUE(plain.out.done) << tape << " error " << int(plain.out.error_code);
    ASSERT_TRUE(ramp.out.done) << tape;
    EXPECT_TRUE(keys(plain.rec) == keys(ramp.rec)) << tape;
    EXPECT_EQ(plain.out.pos_x, ramp.out.pos_x);
    EXPECT_EQ(plain.out.pos_y, ramp.out.pos_y);
    EXPECT_GT(ramp.rec.cycles, plain.rec.cycles) << "a ramp only stretches time";
  }
}

TEST_P(GoldenRamp, TheRateStartsAtRestMovesOneStepPerClockAndEndsEachBlockAtMostOneStep) {
  const InterpConfig cfg = ramped(GetParam(), 500);
  const uint64_t du = cfg.accel_step;
  ASSERT_GT(du, 0u);
  for (const std::string& tape : tapes()) {
    const RampRun r = play(cfg, tape);
    ASSERT_TRUE(r.out.done) << tape;
    uint64_t prev = 0;
    for (size_t c = 0; c < r.rate.size(); ++c) {
      const uint64_t u = r.rate[c];
      if (r.loaded[c]) {
        EXPECT_LE(prev, du) << "a block ends at most one step above rest, clock " << c + 1;
        EXPECT_EQ(u, 0u) << "a block starts at rest, clock " << c + 1;
      } else {
        EXPECT_LE(u > prev ? u - prev : prev - u, du) << "clock " << c + 1;
      }
      EXPECT_EQ(u % du, 0u);
      prev = u;
    }
  }
}

// Speed between two pulses of an axis: 1 BLU over their interval; acceleration: the change
// between neighbouring intervals over the time between their middles. The allowance: the
// DDA places an axis's pulse on an iteration, up to one iteration (M / u clocks) after its
// ideal time, and on a clock; an error e in an interval T moves the speed 1/T by up to
// e / T^2.
TEST_P(GoldenRamp, EachAxisAccelerationMeasuredAtThePulsesStaysWithinTheLimit) {
  const double accel = 500;  // mm/s^2
  const InterpConfig cfg = ramped(GetParam(), accel);
  const double limit = static_cast<double>(cfg.accel_step) / static_cast<double>(cfg.feed_modulus);
  for (const std::string& tape : tapes()) {
    const RampRun r = play(cfg, tape);
    ASSERT_TRUE(r.out.done) << tape;
    for (int axis = 0; axis < 2; ++axis) {
      std::vector<uint64_t> t;
      for (const auto& p : r.rec.pulses)
        if (p.axis == axis) t.push_back(p.cycle);
      for (size_t i = 1; i + 1 < t.size(); ++i) {
        const double t1 = static_cast<double>(t[i] - t[i - 1]);
        const double t2 = static_cast<double>(t[i + 1] - t[i]);
        const double a = std::abs(1 / t2 - 1 / t1) / ((t1 + t2) / 2);
        const double u = static_cast<double>(r.rate[t[i] - 1]);
        const double e = 1 + static_cast<double>(cfg.feed_modulus) / std::max(u, 1.0);
        const double quantum = e * (1 / (t1 * t1) + 1 / (t2 * t2)) / ((t1 + t2) / 2);
        EXPECT_LE(a, limit + quantum) << "axis " << axis << " pulse " << i << " at clock " << t[i];
      }
    }
  }
}

// Braking on the exact slack ends a block on time: it lasts no longer than the ideal
// trapezoid (or triangle) of its N iterations at the rate limit and target, plus a few
// clocks of quantisation, so its last iterations never creep at one ramp step.
TEST_P(GoldenRamp, EachBlockLastsItsIdealTrapezoidWithinAFewClocks) {
  InterpConfig cfg = interp_config(12e6);  // a real board's clock and acceleration
  cfg.arch = GetParam();
  cfg.accel_step = InterpConfig::accel_step_for(500, 12e6, cfg.frac_digits, cfg.feed_modulus);
  // 1 mm at 600 mm/min (a trapezoid), 0.01 mm at 600 mm/min (a triangle), an arc.
  const std::string tape =
      "%\nG17 G21 G91 G93\nN1 G01 X1.000 Y0.300 F600.000\nN2 G01 X0.010 Y0.000 F60000.000\n"
      "N3 G02 X0.500 Y-0.500 I0.000 J-0.500 F600.000\nM02\n%\n";
  const RampRun r = play(cfg, tape);
  ASSERT_TRUE(r.out.done);
  const double m = static_cast<double>(cfg.feed_modulus);
  const double a = static_cast<double>(cfg.accel_step) / m;  // iterations per clock^2
  std::vector<size_t> loads;
  for (size_t c = 0; c < r.loaded.size(); ++c)
    if (r.loaded[c]) loads.push_back(c);
  ASSERT_EQ(loads.size(), 3u);
  loads.push_back(r.rate.size());
  for (size_t b = 0; b < 3; ++b) {
    // N from the block's cruise: the largest rate it reached and its pulses' count is not
    // enough for an arc, so take N as the phase it consumed: sum of u over its clocks / M.
    double phase = 0, peak = 0;
    for (size_t c = loads[b]; c < loads[b + 1]; ++c) {
      phase += static_cast<double>(r.rate[c]);
      peak = std::max(peak, static_cast<double>(r.rate[c]) / m);
    }
    const double n = std::floor(phase / m);
    const double ideal = n >= peak * peak / a ? n / peak + peak / a : 2 * std::sqrt(n / a);
    const double took = static_cast<double>(loads[b + 1] - loads[b]);
    EXPECT_LE(took, ideal * 1.001 + 20) << "block " << b + 1 << ": " << took << " clocks";
  }
}

// A hold mid-block brakes at the limit to rest and then emits nothing until start; the run
// ends with the pulses of the run without the hold. Without the ramp a hold stops at once.
TEST_P(GoldenRamp, AHoldStopsThePulsesUntilStartAndKeepsThePath) {
  for (uint64_t accel : {uint64_t{0}, uint64_t{500}}) {
    const InterpConfig cfg = ramped(GetParam(), static_cast<double>(accel));
    const RampRun plain = play(cfg, kArcTape);
    ASSERT_TRUE(plain.out.done);
    const uint64_t hold_at = plain.rec.cycles / 3, start_at = hold_at + 20000;
    GoldenInterp dut(cfg);
    const std::vector<uint8_t> frames = frames_of(kArcTape);
    FrameSource source(frames, 1, {{hold_at, OperatorEvent::kHold}, {start_at, OperatorEvent::kStart}});
    OutputRecorder rec;
    uint64_t rest = 0;  // the first clock of the hold at rest
    for (uint64_t c = 1; c <= kMaxCycles && !dut.outputs().done; ++c) {
      const bool ready = dut.outputs().frame_ready;
      dut.tick(source.inputs());
      source.clock(ready);
      rec.observe(dut.cycle(), dut.outputs());
      // At rest: without the ramp at once (the clock after the press), with it once u is 0.
      if (c > hold_at && c <= start_at && (accel == 0 || dut.rate() == 0) && rest == 0) rest = c;
    }
    ASSERT_TRUE(dut.outputs().done);
    ASSERT_GT(rest, 0u) << "the hold never reached rest";
    for (const auto& p : rec.pulses)
      EXPECT_FALSE(p.cycle > rest + 64 && p.cycle <= start_at) << "a pulse at clock " << p.cycle << " while held";
    EXPECT_TRUE(keys(plain.rec) == keys(rec));
    EXPECT_EQ(plain.out.pos_x, dut.outputs().pos_x);
    EXPECT_EQ(plain.out.pos_y, dut.outputs().pos_y);
  }
}

INSTANTIATE_TEST_SUITE_P(Archs, GoldenRamp, ::testing::Values(Arch::kSerial, Arch::kParallel),
                         [](const auto& info) { return std::string(arch_name(info.param)); });

}  // namespace
}  // namespace ncinterp
