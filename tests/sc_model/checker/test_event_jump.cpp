// Event jumping (GoldenInterp::quiet_ticks/skip, FrameSource::steady_clocks/skip,
// run_engine_jumping): a jumped run must tick at every clock where a clocked run's outputs
// change and show the same outputs there, and a check run jumped must give the same verdict,
// errors, timing and violations as one run clock by clock.
// Idea: the clocked run (golden_trace) is the reference; the jumped run records the clocks
// it ticked and what it skipped; every change of the reference must fall on a ticked clock
// with equal outputs, and every skipped clock must repeat the outputs before it.
#include <gtest/gtest.h>

#include <random>

#include "checker_test_support.h"
#include "engine_run.h"
#include "frame_source.h"
#include "interp_top.h"
#include "tape/tape.h"

namespace ncinterp::checker {
namespace {

// Lets every clock the engine and the reader allow be skipped (no checker in the way).
struct NoChecker {
  uint64_t quiet_limit() const { return UINT64_MAX; }
  void observe_quiet(uint64_t cycle, const InterpOutputs&) { skipped_to.push_back(cycle); }
  std::vector<uint64_t> skipped_to;
};

tape::Block quadrant(uint32_t n, int64_t r, int q, bool ccw, uint64_t feed) {
  const int64_t ax[4] = {r, 0, -r, 0}, ay[4] = {0, r, 0, -r};
  const int from = ccw ? q : (q + 1) % 4, to = ccw ? (q + 1) % 4 : q;
  return {n, ccw ? tape::Motion::kArcCcw : tape::Motion::kArcCw, ax[to] - ax[from],
          ay[to] - ay[from], -ax[from], -ay[from], feed};
}

// Lines, arcs and (rapids) G00 blocks, at feeds from saturated to
// a few hundred clocks per iteration.
tape::Program mixed_program(std::mt19937& rng, bool rapids) {
  tape::Program p;
  std::uniform_int_distribution<int64_t> inc(-3000, 3000), radius(20, 2000);
  std::uniform_int_distribution<uint64_t> feed(300000, 60000000);  // 100 .. 20000 clocks a block
  for (uint32_t n = 1; n <= 12; ++n) {
    const int kind = static_cast<int>(rng() % (rapids ? 4 : 3));
    if (kind == 0)
      p.blocks.push_back(quadrant(n, radius(rng), static_cast<int>(rng() % 4), rng() & 1, feed(rng)));
    else if (kind == 3)
      p.blocks.push_back({n, tape::Motion::kRapid, inc(rng), inc(rng), 0, 0, 0});
    else
      p.blocks.push_back({n, tape::Motion::kLine, inc(rng), inc(rng), 0, 0, feed(rng)});
  }
  return p;
}

// Runs jumped and compares with the clocked trace; returns the clocks skipped.
uint64_t expect_jumped_equals_clocked(const std::vector<uint8_t>& frames, const InterpConfig& cfg,
                                      uint64_t cpf, const GoldenInterp::Fault* fault,
                                      const std::vector<OperatorEvent>& events = {}) {
  const std::vector<InterpOutputs> ref = test::golden_trace(frames, cfg, cpf, fault, events);
  GoldenInterp dut(cfg);
  if (fault) dut.inject(*fault);
  FrameSource source(frames, cpf, events);
  NoChecker nc;
  std::vector<std::pair<uint64_t, InterpOutputs>> ticked;
  const RunEnd end = run_engine_jumping(dut, source, ref.size() + 100, nc,
                                        [&](uint64_t c, const InterpOutputs& o) { ticked.push_back({c, o}); });
  EXPECT_EQ(end.cycles + 1, ref.size()) << "the runs end at different clocks";
  EXPECT_EQ(end.last, ref.back());
  std::vector<bool> was_ticked(ref.size() + 1, false);
  for (const auto& [c, o] : ticked) {
    if (c >= ref.size()) {
      ADD_FAILURE() << "ticked clock " << c << " after the clocked run's end";
      continue;
    }
    was_ticked[c] = true;
    EXPECT_EQ(o, ref[c]) << "outputs differ at clock " << c;
  }
  uint64_t skipped = 0;
  for (size_t c = 1; c < ref.size(); ++c) {
    if (was_ticked[c]) continue;
    ++skipped;
    EXPECT_EQ(ref[c], ref[c - 1]) << "clock " << c << " was skipped but its outputs change";
  }
  return skipped;
}

TEST(EventJump, JumpedRunEqualsClockedAtEveryEvent) {
  std::mt19937 rng(4242);
  uint64_t skipped = 0, cases = 0;
  for (bool serial : {false, true}) {
    for (uint64_t cpf : {1ull, 7ull, 300ull}) {
      for (int k = 0; k < 4; ++k) {
        InterpConfig cfg;
        cfg.arch = serial ? Arch::kSerial : Arch::kParallel;
        cfg.feed_modulus = 60ull * 100000ull * 1000ull;  // a 100 kHz clock: short runs
        // The last run of each kind ramps (2000 mm/s^2): only its cruises are quiet; the
        // operator overrides it (slower, back to 100 %, faster, the rapids at 50 %).
        std::vector<OperatorEvent> events;
        if (k == 3) {
          cfg.accel_step = InterpConfig::accel_step_for(2000, 1e5, 3, cfg.feed_modulus);
          events = {{20000, OperatorEvent::kFeedOverride, 77}, {45000, OperatorEvent::kRapidOverride, 64},
                    {60000, OperatorEvent::kFeedOverride, kOverrideOne},
                    {90000, OperatorEvent::kFeedOverride, 200}};
        }
        tape::Program p = mixed_program(rng, true);
        if (k == 2) {
          // M words: the tool on and off, and two pauses (M00, and M01 with the switch on)
          // that cycle start presses every 7000 clocks end.
          p.blocks[2].tool_on = true;
          p.blocks[6].tool_off = true;
          tape::Block pause{40, tape::Motion::kRapid};
          pause.still = pause.stop = true;
          p.blocks.insert(p.blocks.begin() + 4, pause);
          pause.n = 41;
          pause.stop = false;
          pause.optional_stop = true;
          p.blocks.insert(p.blocks.begin() + 9, pause);
          events.push_back({1, OperatorEvent::kOptionalStop, 1});
          for (uint64_t c = 7000; c < 2'000'000; c += 7000) events.push_back({c, OperatorEvent::kStart});
        }
        skipped += expect_jumped_equals_clocked(test::frames_of(p), cfg, cpf, nullptr, events);
        ++cases;
      }
    }
  }
  EXPECT_GT(skipped, 0u) << "nothing was skipped in " << cases << " runs: the test proves nothing";
}

TEST(EventJump, FaultsActAtTheirClockInAJumpedRun) {
  std::mt19937 rng(99);
  InterpConfig cfg;
  cfg.feed_modulus = 60ull * 100000ull * 1000ull;
  for (auto kind : {GoldenInterp::Fault::kLostPulse, GoldenInterp::Fault::kStuckStep,
                    GoldenInterp::Fault::kAccumulatorOffByOne, GoldenInterp::Fault::kWrongDirection}) {
    const tape::Program p = mixed_program(rng, false);
    GoldenInterp::Fault f;
    f.kind = kind;
    f.cycle = 5000 + rng() % 20000;
    f.axis = static_cast<int>(rng() & 1);
    expect_jumped_equals_clocked(test::frames_of(p), cfg, 7, &f);
  }
}

TEST(EventJump, ACheckJumpedReportsAsOneClockByClock) {
  std::mt19937 rng(7);
  const tape::Program p = test::random_line_program(rng, 20, 12, 60ull * 1000000ull * 1000ull, 50, 5000);
  const std::vector<uint8_t> frames = test::frames_of(p);
  CheckSetup s;
  s.reader_cps = 50000;
  s.every_clock = true;
  const uint64_t clocks = run_check(frames, nullptr, s).checker->cycles();
  for (bool fault : {false, true}) {
    if (fault) s.fault = GoldenInterp::Fault{GoldenInterp::Fault::kLostPulse, clocks / 2, 0};
    s.every_clock = true;
    const CheckOutcome a = run_check(frames, nullptr, s);
    s.every_clock = false;
    const CheckOutcome b = run_check(frames, nullptr, s);
    EXPECT_EQ(a.checker->cycles(), b.checker->cycles());
    EXPECT_EQ(a.checker->gap_clocks(), b.checker->gap_clocks());
    EXPECT_EQ(a.checker->pulse_count(), b.checker->pulse_count());
    EXPECT_EQ(a.checker->path_error().max, b.checker->path_error().max);
    ASSERT_EQ(a.checker->violations().size(), b.checker->violations().size());
    for (size_t k = 0; k < a.checker->violations().size(); ++k) {
      EXPECT_EQ(a.checker->violations()[k].rule, b.checker->violations()[k].rule);
      EXPECT_EQ(a.checker->violations()[k].cycle, b.checker->violations()[k].cycle);
    }
    for (size_t k = 0; k < a.checker->results().size(); ++k)
      EXPECT_EQ(a.checker->results()[k].clocks, b.checker->results()[k].clocks) << "block " << k;
    EXPECT_EQ(a.passed(), !fault);
  }
}

}  // namespace
}  // namespace ncinterp::checker
