// Injected faults (golden model test hook, docs/interpolator.md section 9) must be caught by
// the trajectory checker and by the lock-step scoreboard (golden vs verilated RTL), each at
// the right block and clock.
// Ground truth, from the engines only: the first clock at which the faulty golden run's
// outputs differ from the clean run's, and the block N the outputs show there. The checker's
// first report and the scoreboard's mismatch must both name that clock and that N. A fault
// that changes no output (an accumulator nudge that never moves a carry) must not be
// reported by either.
#include <gtest/gtest.h>

#include <iostream>
#include <random>

#include "checker_test_support.h"
#include "check_session.h"
#include "frame_source.h"
#ifdef NCINTERP_TEST_HAS_COSIM
#include "lockstep.h"
#endif

namespace ncinterp::checker {
namespace {

using Fault = GoldenInterp::Fault;

const char* kind_name(Fault::Kind k) {
  switch (k) {
    case Fault::kLostPulse: return "lost pulse";
    case Fault::kStuckStep: return "stuck step";
    case Fault::kAccumulatorOffByOne: return "accumulator off by one";
    case Fault::kWrongDirection: return "wrong direction";
    default: return "none";
  }
}

struct Manifest {
  bool visible = false;
  uint64_t cycle = 0;
  uint32_t block_n = 0;
};

Manifest first_difference(const std::vector<InterpOutputs>& clean, const std::vector<InterpOutputs>& faulty) {
  Manifest m;
  const size_t n = std::min(clean.size(), faulty.size());
  for (size_t c = 0; c < n; ++c) {
    if (clean[c] != faulty[c]) return {true, c, faulty[c].block_n};
  }
  if (clean.size() != faulty.size()) return {true, n, faulty.empty() ? 0 : faulty[n - 1].block_n};
  return m;
}

const Violation* earliest(const TrajectoryChecker& c) {
  const Violation* best = nullptr;
  for (const Violation& v : c.violations())
    if (!best || v.cycle < best->cycle) best = &v;
  return best;
}

class FaultDetection : public ::testing::TestWithParam<Fault::Kind> {};

TEST_P(FaultDetection, CheckerAndScoreboardReportTheFirstDifferingClockAndBlock) {
  const Fault::Kind kind = GetParam();
  std::mt19937 rng(100 + static_cast<int>(kind));
  CheckSetup setup;
  setup.reader_cps = 1e6;  // one frame per clock
  const InterpConfig cfg = interp_config(setup.clock_hz, setup.format);
  int visible = 0, invisible = 0;
  // An accumulator upset shows only where it moves a carry to another iteration (the DDA's
  // pulse counters keep a block's pulse count), so most are invisible: more trials.
  const int trials = kind == Fault::kAccumulatorOffByOne ? 100 : 40;
  for (int trial = 0; trial < trials; ++trial) {
    const tape::Program p = test::random_line_program(rng, 8, 9, cfg.feed_modulus, 60, 1500);
    const std::vector<uint8_t> frames = test::frames_of(p);
    const auto clean = test::golden_trace(frames, cfg, 1);
    Fault f;
    f.kind = kind;
    f.axis = trial % 2;
    f.cycle = std::uniform_int_distribution<uint64_t>(1, clean.size() - 1)(rng);
    const auto faulty = test::golden_trace(frames, cfg, 1, &f);
    const Manifest m = first_difference(clean, faulty);
    setup.fault = f;
    const CheckOutcome out = run_check(frames, nullptr, setup);
    const std::string what = std::string(kind_name(kind)) + " on " + (f.axis ? "Y" : "X") +
                             " at cycle " + std::to_string(f.cycle) + " (trial " +
                             std::to_string(trial) + ")";
#ifdef NCINTERP_TEST_HAS_COSIM
    cosim::Options co;
    co.config = cfg;
    co.cycles_per_frame = 1;
    co.fault = f;
    const cosim::Result sb = cosim::run_lockstep(frames, co);
#endif
    if (!m.visible) {
      ++invisible;
      EXPECT_EQ(out.checker->violation_count(), 0u) << what << ": no output changed, yet reported";
#ifdef NCINTERP_TEST_HAS_COSIM
      EXPECT_FALSE(sb.mismatch) << what << ": no output changed, yet the scoreboard reports "
                                << cosim::describe(*sb.mismatch);
#endif
      continue;
    }
    ++visible;
    const Violation* v = earliest(*out.checker);
    ASSERT_NE(v, nullptr) << what << ": outputs differ from cycle " << m.cycle << ", not reported";
    EXPECT_EQ(v->cycle, m.cycle) << what << ": " << rule_name(v->rule) << " " << v->detail;
    EXPECT_EQ(v->n, m.block_n) << what;
#ifdef NCINTERP_TEST_HAS_COSIM
    ASSERT_TRUE(sb.mismatch) << what << ": the scoreboard saw no mismatch";
    EXPECT_EQ(sb.mismatch->cycle, m.cycle) << what << ": " << cosim::describe(*sb.mismatch);
    EXPECT_EQ(sb.mismatch->block, m.block_n) << what << ": " << cosim::describe(*sb.mismatch);
#endif
  }
  std::cout << kind_name(kind) << ": " << visible << " faults changed the outputs, " << invisible << " changed nothing\n";
  // The test means something only if most faults show.
  EXPECT_GE(visible, kind == Fault::kAccumulatorOffByOne ? 10 : 30) << invisible << " invisible";
}

TEST(FaultDetection, ScoreboardIsInThisBuild) {
#ifndef NCINTERP_TEST_HAS_COSIM
  FAIL() << "no verilated RTL / cosim library in this build: scoreboard half not run";
#endif
}

INSTANTIATE_TEST_SUITE_P(AllKinds, FaultDetection,
                         ::testing::Values(Fault::kLostPulse, Fault::kStuckStep,
                                           Fault::kAccumulatorOffByOne, Fault::kWrongDirection),
                         [](const ::testing::TestParamInfo<Fault::Kind>& info) {
                           switch (info.param) {
                             case Fault::kLostPulse: return std::string("LostPulse");
                             case Fault::kStuckStep: return std::string("StuckStep");
                             case Fault::kAccumulatorOffByOne: return std::string("AccumulatorOffByOne");
                             default: return std::string("WrongDirection");
                           }
                         });

}  // namespace
}  // namespace ncinterp::checker
