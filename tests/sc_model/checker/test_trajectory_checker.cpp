// The trajectory checker on clean golden runs (no rule may fire, the numbers must match an
// independent computation) and on hand-made output sequences that break one rule each.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>

#include "checker_test_support.h"
#include "check_session.h"
#include "dda_serial.h"
#include "trajectory_checker.h"

namespace ncinterp::checker {
namespace {

using test::frames_of;

// What the checker is told of the machine cfg (as check_session does).
CheckerOptions options_for(const InterpConfig& cfg) {
  CheckerOptions co;
  co.feed_modulus = cfg.feed_modulus;
  co.inc_width = cfg.inc_width;
  co.lead_bits = SerialDda::player_lead_bits(cfg);
  co.rapid_step = cfg.rapid_step_on_port();
  co.accel_step = cfg.accel_step;
  return co;
}

// A 1 MHz machine of `arch` with a reader as fast as the clock, ramped at accel_mm_s2 (0:
// not), as the operator tests play it.
CheckSetup at_1mhz(Arch arch, double accel_mm_s2) {
  CheckSetup setup;
  setup.clock_hz = 1e6;
  setup.arch = arch;
  setup.accel_mm_s2 = accel_mm_s2;
  setup.reader_cps = 1e6;
  return setup;
}

// A random program of `blocks` lines of 12-bit moves, each 30 000 to 60 000 clocks long at
// `setup`'s clock: the operator tests' tape.
tape::Program operator_program(std::mt19937& rng, const CheckSetup& setup, int blocks) {
  const uint64_t modulus = interp_config(setup.clock_hz, setup.format).feed_modulus;
  return test::random_line_program(rng, blocks, 12, modulus, 30000, 60000);
}

std::string first_violation(const TrajectoryChecker& c) {
  if (c.violations().empty()) return "none";
  const Violation& v = c.violations().front();
  return std::string(rule_name(v.rule)) + " N" + std::to_string(v.n) + " cycle " +
         std::to_string(v.cycle) + ": " + v.detail;
}

// Random line programs on the golden model pass every rule: the documented schedule of
// every pulse, the block times and the path bound, in both archs (the serial player takes
// 2P = 32 clocks per iteration, so many of these blocks are saturated).
void clean_random_line_programs_pass_every_rule(Arch arch) {
  std::mt19937 rng(11);
  CheckSetup setup;
  setup.clock_hz = 1e6;
  setup.arch = arch;
  int saturated = 0, unsaturated = 0;
  const uint64_t modulus = interp_config(setup.clock_hz, setup.format).feed_modulus;
  for (int prog = 0; prog < 150; ++prog) {
    const tape::Program p = test::random_line_program(rng, 12, prog % 3 == 0 ? 16 : 9, modulus, 100, 3000);
    // Fast reader for most, a slow one (gaps between blocks) for some.
    setup.reader_cps = prog % 5 == 0 ? 2e4 : 1e6;
    const CheckOutcome out = run_check(frames_of(p), nullptr, setup);
    ASSERT_TRUE(out.passed()) << "program " << prog << ": " << first_violation(*out.checker);
    const TrajectoryChecker& c = *out.checker;
    for (size_t k = 0; k < p.blocks.size(); ++k) {
      const BlockResult& r = c.results()[k];
      ASSERT_TRUE(r.finished);
      EXPECT_EQ(r.pulses[0], static_cast<uint64_t>(std::llabs(p.blocks[k].dx)));
      EXPECT_EQ(r.pulses[1], static_cast<uint64_t>(std::llabs(p.blocks[k].dy)));
      EXPECT_LE(r.path.max, r.bound + 1e-9);
      // Documented block time: ceil(M/F), never below 1/F, less than one clock late.
      if (!r.saturated) {
        EXPECT_GE(static_cast<double>(r.clocks), r.ideal_clocks - 1e-9);
        EXPECT_LT(static_cast<double>(r.clocks), r.ideal_clocks + 1.0);
      }
      ++(r.saturated ? saturated : unsaturated);
    }
    int64_t x = 0, y = 0;
    for (const auto& b : p.blocks) x += b.dx, y += b.dy;
    EXPECT_EQ(c.position(), (GridPoint{x, y}));
  }
  EXPECT_GT(saturated, 100);
  EXPECT_GT(unsaturated, 100);
}

TEST(TrajectoryChecker, CleanRandomLineProgramsPassEveryRuleOnTheParallelPlayer) {
  clean_random_line_programs_pass_every_rule(Arch::kParallel);
}

TEST(TrajectoryChecker, CleanRandomLineProgramsPassEveryRuleOnTheSerialPlayer) {
  clean_random_line_programs_pass_every_rule(Arch::kSerial);
}

// The violations of program p played on setup's machine ramped 8 times steeper than the
// checker expects (the engine at 8 du, the checker told du).
std::vector<Violation> steeper_ramp_violations(const tape::Program& p, const CheckSetup& setup) {
  InterpConfig cfg = interp_config(setup.clock_hz, setup.format, setup.rapid_mm_min, setup.accel_mm_s2);
  cfg.arch = setup.arch;
  const CheckerOptions co = options_for(cfg);
  cfg.accel_step *= 8;
  const std::vector<InterpOutputs> trace = test::golden_trace(frames_of(p), cfg, 1);
  TrajectoryChecker c(lay_out(p), nullptr, co);
  for (size_t t = 0; t < trace.size(); ++t) c.observe(t, trace[t]);
  c.finish(trace.back());
  return c.violations();
}

// With the feed ramp (--accel) the same programs pass every rule, the schedule rule now
// the DDA's order of pulses, the duration rule at least the programmed time, and the
// acceleration rule; a run ramped 8 times steeper than the checker's limit fails the
// acceleration rule, and nothing else.
TEST(TrajectoryChecker, RampedRunsPassEveryRuleAndASteeperRampFailsTheAccelerationRule) {
  for (Arch arch : {Arch::kSerial, Arch::kParallel}) {
    std::mt19937 rng(12);
    CheckSetup setup = at_1mhz(arch, 500);
    const uint64_t modulus = interp_config(setup.clock_hz, setup.format).feed_modulus;
    for (int prog = 0; prog < 30; ++prog) {
      const tape::Program p = test::random_line_program(rng, 6, prog % 3 == 0 ? 16 : 9, modulus, 100, 300000);
      const CheckOutcome out = run_check(frames_of(p), nullptr, setup);
      ASSERT_TRUE(out.passed()) << arch_name(arch) << " program " << prog << ": " << first_violation(*out.checker);
    }
    const std::vector<Violation> steep =
        steeper_ramp_violations(test::random_line_program(rng, 6, 12, modulus, 30000, 60000), setup);
    ASSERT_FALSE(steep.empty()) << arch_name(arch);
    for (const Violation& v : steep) EXPECT_EQ(v.rule, Rule::kAcceleration) << arch_name(arch) << ": " << v.detail;
  }
}

// A circle of four quadrant arcs (G03) of radius r BLU about (r, 0), from the origin, each
// lasting about `clocks` at modulus M.
tape::Program circle_program(int64_t r, uint64_t modulus, uint64_t clocks) {
  tape::Program p;
  // Start of each quadrant relative to the centre, counterclockwise: (-r, 0), (0, -r), ...
  const int64_t sx[4] = {-r, 0, r, 0}, sy[4] = {0, -r, 0, r};
  for (int q = 0; q < 4; ++q) {
    tape::Block b;
    b.n = static_cast<uint32_t>(q + 1);
    b.motion = tape::Motion::kArcCcw;
    b.i = -sx[q];
    b.j = -sy[q];
    b.dx = sx[(q + 1) % 4] - sx[q];
    b.dy = sy[(q + 1) % 4] - sy[q];
    b.feed = modulus / clocks;
    p.blocks.push_back(b);
  }
  return p;
}

// Arcs: their pulses come in the circle DDA's order, ramped or not, and ramped the
// iteration rate keeps the acceleration limit, as on lines: a ramped circle passes every
// rule with its acceleration measured, an arc ramped 8 times steeper fails the
// acceleration rule and nothing else, and an arc whose pulses swap two clocks fails the
// schedule rule.
TEST(TrajectoryChecker, ArcsKeepTheCircleDdasOrderAndTheAccelerationLimit) {
  for (Arch arch : {Arch::kSerial, Arch::kParallel}) {
    CheckSetup setup = at_1mhz(arch, 500);
    const uint64_t modulus = interp_config(setup.clock_hz, setup.format).feed_modulus;
    const tape::Program p = circle_program(3000, modulus, 120000);
    const CheckOutcome out = run_check(frames_of(p), nullptr, setup);
    ASSERT_TRUE(out.passed()) << arch_name(arch) << ": " << first_violation(*out.checker);
    for (const BlockResult& r : out.checker->results()) {
      EXPECT_GT(r.accel_ratio, 0.1) << arch_name(arch) << ": the arcs' ramps were not measured";
      EXPECT_LE(r.accel_ratio, 1.0);
    }

    const std::vector<Violation> steep = steeper_ramp_violations(p, setup);
    ASSERT_FALSE(steep.empty()) << arch_name(arch);
    for (const Violation& v : steep) EXPECT_EQ(v.rule, Rule::kAcceleration) << arch_name(arch) << ": " << v.detail;

    // Unramped, the first arc's first X-only pulse and the Y-only pulse after it swap clocks.
    InterpConfig cfg = interp_config(setup.clock_hz, setup.format);
    cfg.arch = arch;
    std::vector<InterpOutputs> swapped = test::golden_trace(frames_of(p), cfg, 1);
    size_t x_only = 0, y_only = 0;
    for (size_t t = 0; t < swapped.size() && !y_only; ++t) {
      if (swapped[t].step_x && !swapped[t].step_y && !x_only) x_only = t;
      else if (x_only && swapped[t].step_y && !swapped[t].step_x) y_only = t;
    }
    ASSERT_GT(y_only, x_only);
    std::swap(swapped[x_only].step_x, swapped[y_only].step_x);
    std::swap(swapped[x_only].step_y, swapped[y_only].step_y);
    // The position counters follow the pulses as the engine would show them.
    for (size_t t = x_only; t < y_only; ++t) {
      swapped[t].pos_x -= swapped[x_only].dir_x ? 1 : -1;
      swapped[t].pos_y += swapped[x_only].dir_y ? 1 : -1;
    }
    TrajectoryChecker order(lay_out(p), nullptr, options_for(cfg));
    for (size_t t = 0; t < swapped.size(); ++t) order.observe(t, swapped[t]);
    order.finish(swapped.back());
    bool schedule = false;
    for (const Violation& v : order.violations()) schedule = schedule || v.rule == Rule::kSchedule;
    EXPECT_TRUE(schedule) << arch_name(arch);
  }
}

// A tape without N words (every block the same N) shows no load on the outputs between
// its blocks. Ramped or held, each block is over once all its pulses have come: such runs
// pass every rule with every block's own pulses, and a checker told of one pulse more in
// the first block than the engine played fails.
TEST(TrajectoryChecker, BlocksWithTheSameNRampedOrHeldAreToldApartByTheirPulses) {
  for (Arch arch : {Arch::kSerial, Arch::kParallel}) {
    std::mt19937 rng(14);
    CheckSetup setup = at_1mhz(arch, 0);
    tape::Program p = operator_program(rng, setup, 8);
    for (tape::Block& b : p.blocks) b.n = 7;
    for (const double accel : {500.0, 0.0}) {
      setup.accel_mm_s2 = accel;
      setup.events = {{50000, OperatorEvent::kHold}, {90000, OperatorEvent::kStart}};
      const CheckOutcome out = run_check(frames_of(p), nullptr, setup);
      ASSERT_TRUE(out.passed()) << arch_name(arch) << " accel " << accel << ": " << first_violation(*out.checker);
      for (size_t k = 0; k < p.blocks.size(); ++k) {
        EXPECT_EQ(out.checker->results()[k].pulses[0], static_cast<uint64_t>(std::llabs(p.blocks[k].dx)));
        EXPECT_EQ(out.checker->results()[k].pulses[1], static_cast<uint64_t>(std::llabs(p.blocks[k].dy)));
      }
    }
    InterpConfig cfg = interp_config(setup.clock_hz, setup.format, setup.rapid_mm_min, 500.0);
    cfg.arch = arch;
    CheckerOptions co = options_for(cfg);
    const std::vector<InterpOutputs> trace = test::golden_trace(frames_of(p), cfg, 1);
    tape::Program told = p;
    told.blocks[0].dx += told.blocks[0].dx >= 0 ? 1 : -1;
    TrajectoryChecker c(lay_out(told), nullptr, co);
    for (size_t t = 0; t < trace.size(); ++t) c.observe(t, trace[t]);
    c.finish(trace.back());
    EXPECT_GT(c.violation_count(), 0u) << arch_name(arch);
  }
}

// Feed hold in check (--events): a run held and started passes every rule; a checker told
// of a hold the engine never got reports the pulses in the held stretch, and only them.
TEST(TrajectoryChecker, PulsesWhileHeldFailTheHeldRule) {
  for (Arch arch : {Arch::kSerial, Arch::kParallel}) {
    std::mt19937 rng(13);
    CheckSetup setup = at_1mhz(arch, 500);
    const tape::Program p = operator_program(rng, setup, 6);
    setup.events = {{50000, OperatorEvent::kHold}, {250000, OperatorEvent::kStart}};
    const CheckOutcome held = run_check(frames_of(p), nullptr, setup);
    ASSERT_TRUE(held.passed()) << arch_name(arch) << ": " << first_violation(*held.checker);
    // The hold's stop: its last pulse after the press, braking, and the position there.
    ASSERT_EQ(held.checker->hold_stops().size(), 1u);
    const HoldStop& stop = held.checker->hold_stops()[0];
    EXPECT_EQ(stop.pressed, 50000u);
    EXPECT_EQ(stop.resumed, 250000u);
    EXPECT_GT(stop.at_rest, stop.pressed);
    const std::vector<PulseSample>& pulses = held.checker->pulses();
    const auto after = std::find_if(pulses.begin(), pulses.end(), [&](const PulseSample& s) { return s.cycle > stop.at_rest; });
    ASSERT_NE(after, pulses.begin());
    EXPECT_EQ(std::prev(after)->cycle, stop.at_rest);
    EXPECT_EQ(std::prev(after)->position, stop.position);
    ASSERT_NE(after, pulses.end());
    EXPECT_GT(after->cycle, stop.resumed);
    // The engine without the presses, the checker with them.
    InterpConfig cfg = interp_config(setup.clock_hz, setup.format, setup.rapid_mm_min, setup.accel_mm_s2);
    cfg.arch = arch;
    CheckerOptions co = options_for(cfg);
    co.operator_holds = true;
    co.holds = {{50000, 250000}};
    co.hold_settle = 40000;
    const std::vector<InterpOutputs> trace = test::golden_trace(frames_of(p), cfg, 1);
    TrajectoryChecker c(lay_out(p), nullptr, co);
    for (size_t t = 0; t < trace.size(); ++t) c.observe(t, trace[t]);
    c.finish(trace.back());
    ASSERT_GT(c.violation_count(), 0u) << arch_name(arch);
    for (const Violation& v : c.violations()) {
      EXPECT_EQ(v.rule, Rule::kHeld) << arch_name(arch) << ": " << v.detail;
      EXPECT_GT(v.cycle, 90000u);
      EXPECT_LE(v.cycle, 250000u);
    }
  }
}

// M words in check: a tape with M03, M05 and an M00 still block (cycle start pressed later)
// passes every rule on both archs; a checker whose tape turns the tool on one block later
// than the played one finds the first block's pulses with the tool on (the tool rule, and
// only it); a run no press resumes ends paused, every rule holding up to the pause.
TEST(TrajectoryChecker, ToolOutputFollowsTheTapesM03AndM05) {
  for (Arch arch : {Arch::kSerial, Arch::kParallel}) {
    std::mt19937 rng(17);
    CheckSetup setup = at_1mhz(arch, 500);
    tape::Program p = operator_program(rng, setup, 5);
    p.blocks[1].tool_on = true;
    p.blocks[3].tool_off = true;
    tape::Block pause{p.blocks[2].n, tape::Motion::kRapid};
    pause.still = pause.stop = true;
    p.blocks.insert(p.blocks.begin() + 3, pause);
    const CheckOutcome unpressed = run_check(frames_of(p), nullptr, setup);
    ASSERT_TRUE(unpressed.passed()) << arch_name(arch) << ": " << first_violation(*unpressed.checker);
    EXPECT_TRUE(unpressed.checker->paused());
    EXPECT_TRUE(unpressed.run.last.tool);  // paused between M03 and M05
    setup.events = {{3'000'000, OperatorEvent::kStart}};
    const CheckOutcome played = run_check(frames_of(p), nullptr, setup);
    ASSERT_TRUE(played.passed()) << arch_name(arch) << ": " << first_violation(*played.checker);
    EXPECT_FALSE(played.checker->paused());
    EXPECT_TRUE(played.run.last.done);
    InterpConfig cfg = interp_config(setup.clock_hz, setup.format, setup.rapid_mm_min, setup.accel_mm_s2);
    cfg.arch = arch;
    const std::vector<InterpOutputs> trace = test::golden_trace(frames_of(p), cfg, 1, nullptr, setup.events);
    tape::Program late = p;
    late.blocks[1].tool_on = false;
    late.blocks[2].tool_on = true;
    TrajectoryChecker c(lay_out(late), nullptr, options_for(cfg));
    for (size_t t = 0; t < trace.size(); ++t) c.observe(t, trace[t]);
    c.finish(trace.back());
    ASSERT_GT(c.violation_count(), 0u) << arch_name(arch);
    for (const Violation& v : c.violations()) {
      EXPECT_EQ(v.rule, Rule::kTool) << arch_name(arch) << ": " << v.detail;
      EXPECT_EQ(v.n, p.blocks[1].n) << arch_name(arch);
    }
  }
}

// An E-stop switches the tool off with its error, at its own clock, and that clock may
// still pulse (the stop rule allows none after it): stops pressed at clocks that pulse, in
// a program with the tool on throughout, pass (found by the operator soak).
TEST(TrajectoryChecker, AStopSwitchesTheToolOffAtItsClockWhichMayStillPulse) {
  for (Arch arch : {Arch::kSerial, Arch::kParallel}) {
    std::mt19937 rng(23);
    CheckSetup setup = at_1mhz(arch, 0);
    tape::Program p = operator_program(rng, setup, 4);
    p.blocks.front().tool_on = true;
    InterpConfig cfg = interp_config(setup.clock_hz, setup.format, setup.rapid_mm_min);
    cfg.arch = arch;
    const std::vector<InterpOutputs> trace = test::golden_trace(frames_of(p), cfg, 1, nullptr, {});
    int stops = 0;
    for (size_t t = 10000; t < trace.size() && stops < 12; ++t) {
      if (!(trace[t].step_x || trace[t].step_y)) continue;
      ++stops;
      for (uint64_t pressed : {t - 1, t}) {
        setup.events = {{pressed, OperatorEvent::kEStop}};
        const CheckOutcome out = run_check(frames_of(p), nullptr, setup);
        ASSERT_TRUE(out.passed()) << arch_name(arch) << " stop at " << pressed << ": " << first_violation(*out.checker);
        EXPECT_TRUE(out.checker->stopped());
        EXPECT_FALSE(out.run.last.tool);
      }
    }
    EXPECT_EQ(stops, 12) << arch_name(arch);
  }
}

// Overrides in check (--events): runs at 200 %, at 30 % and changing mid-block pass every
// rule on both archs; a checker not told of the 200 % finds the parallel player's blocks
// shorter than documented (the duration rule, and only it).
TEST(TrajectoryChecker, OverriddenRunsPassAndAFasterOneFailsTheDurationRuleUntold) {
  for (Arch arch : {Arch::kSerial, Arch::kParallel}) {
    std::mt19937 rng(15);
    CheckSetup setup = at_1mhz(arch, 500);
    const tape::Program p = operator_program(rng, setup, 6);
    const std::vector<std::vector<OperatorEvent>> lists = {
        {{1, OperatorEvent::kFeedOverride, 256}},
        {{1, OperatorEvent::kFeedOverride, 38}},
        {{40000, OperatorEvent::kFeedOverride, 200}, {70000, OperatorEvent::kFeedOverride, 0},
         {90000, OperatorEvent::kFeedOverride, 100}}};
    for (size_t k = 0; k < lists.size(); ++k) {
      setup.events = lists[k];
      const CheckOutcome out = run_check(frames_of(p), nullptr, setup);
      ASSERT_TRUE(out.passed()) << arch_name(arch) << " list " << k << ": " << first_violation(*out.checker);
    }
    InterpConfig cfg = interp_config(setup.clock_hz, setup.format, setup.rapid_mm_min, setup.accel_mm_s2);
    cfg.arch = arch;
    CheckerOptions co = options_for(cfg);
    co.operator_holds = true;
    const std::vector<InterpOutputs> trace = test::golden_trace(frames_of(p), cfg, 1, nullptr, lists[0]);
    TrajectoryChecker c(lay_out(p), nullptr, co);
    for (size_t t = 0; t < trace.size(); ++t) c.observe(t, trace[t]);
    c.finish(trace.back());
    if (arch == Arch::kParallel) EXPECT_GT(c.violation_count(), 0u);
    for (const Violation& v : c.violations()) EXPECT_EQ(v.rule, Rule::kDuration) << arch_name(arch) << ": " << v.detail;
  }
}

// E-stop and limits in check (--events): a run stopped mid-program passes every rule and
// ends "stopped" at the press, its last pulse no later, on both archs and with the ramp; a
// checker told of a stop the engine never got reports the pulses after it and the missing
// stop (the stop rule), and only them.
TEST(TrajectoryChecker, StopsEndTheRunAtTheirClockAndPulsesAfterOneFailTheStopRule) {
  for (Arch arch : {Arch::kSerial, Arch::kParallel}) {
    for (double accel : {0.0, 500.0}) {
      std::mt19937 rng(17);
      CheckSetup setup = at_1mhz(arch, accel);
      const tape::Program p = operator_program(rng, setup, 6);
      setup.events = {{90001, OperatorEvent::kLimitY}};
      const CheckOutcome stopped = run_check(frames_of(p), nullptr, setup);
      const std::string what = std::string(arch_name(arch)) + (accel > 0 ? " ramped" : "");
      ASSERT_TRUE(stopped.passed()) << what << ": " << first_violation(*stopped.checker);
      EXPECT_TRUE(stopped.checker->stopped()) << what;
      EXPECT_EQ(stopped.checker->cycles(), 90001u) << what;
      EXPECT_EQ(stopped.run.last.error_code, static_cast<uint8_t>(TapeError::kLimitY));
      ASSERT_FALSE(stopped.checker->pulses().empty());
      EXPECT_LE(stopped.checker->pulses().back().cycle, 90001u);
      // A step output stuck high two clocks after the stop (a fault in the engine): the run
      // is watched past its end, and the pulse breaks the stop rule, and only it.
      setup.fault = GoldenInterp::Fault{GoldenInterp::Fault::kStuckStep, 90003, 0};
      const CheckOutcome stuck = run_check(frames_of(p), nullptr, setup);
      ASSERT_FALSE(stuck.passed()) << what;
      for (const Violation& v : stuck.checker->violations()) {
        EXPECT_EQ(v.rule, Rule::kStop) << what << ": " << v.detail;
        EXPECT_GT(v.cycle, 90001u) << what;
      }
      setup.fault.reset();
      // The engine without the stop, the checker with it.
      InterpConfig cfg = interp_config(setup.clock_hz, setup.format, setup.rapid_mm_min, accel);
      cfg.arch = arch;
      CheckerOptions co = options_for(cfg);
      co.operator_holds = true;
      co.stop_cycle = 90001;
      co.stop_code = static_cast<uint8_t>(TapeError::kLimitY);
      const std::vector<InterpOutputs> trace = test::golden_trace(frames_of(p), cfg, 1);
      TrajectoryChecker c(lay_out(p), nullptr, co);
      for (size_t t = 0; t < trace.size(); ++t) c.observe(t, trace[t]);
      c.finish(trace.back());
      EXPECT_FALSE(c.stopped());
      ASSERT_GE(c.violation_count(), 2u) << what;
      for (const Violation& v : c.violations()) {
        EXPECT_EQ(v.rule, Rule::kStop) << what << ": " << v.detail;
        EXPECT_GT(v.cycle, 90001u);
      }
    }
  }
}

// The pulse path of a chord polygon inscribed in a circle: the checker's total error at
// every pulse equals | |p - c| - R | computed here from the recorded pulse positions.
// G00 plays as a line at the machine's rapid step, S = rapid_step whatever the block's
// length: both archs, on the golden model and the RTL, pass every rule (the documented
// schedule with that S), take M 2^k / S clocks for an unsaturated traverse, and a faster
// rapid rate makes the traverse shorter while the G01 block between keeps its 1/F.
TEST(TrajectoryChecker, RapidTraversesPlayAtTheRapidRateInBothArchs) {
  tape::Program p;
  auto block = [&](uint32_t n, tape::Motion m, int64_t dx, int64_t dy, uint64_t feed) {
    tape::Block b;
    b.n = n;
    b.motion = m;
    b.dx = dx;
    b.dy = dy;
    b.feed = feed;
    p.blocks.push_back(b);
  };
  block(1, tape::Motion::kRapid, 1000, -300, 0);
  block(2, tape::Motion::kLine, 100, 0, 6000000);
  block(3, tape::Motion::kRapid, -1100, 300, 0);
  for (Arch arch : {Arch::kSerial, Arch::kParallel}) {
    for (EngineKind engine : {EngineKind::kGolden, EngineKind::kRtl}) {
      SCOPED_TRACE(std::string(arch_name(arch)) + " " + engine_name(engine));
      uint64_t traverse_clocks[2] = {0, 0};
      for (double rapid : {2000.0, 4000.0}) {
        CheckSetup setup;
        setup.clock_hz = 12e6;  // the boards' clock: no traverse saturates in either arch
        setup.reader_cps = 1e6;
        setup.arch = arch;
        setup.engine = engine;
        setup.rapid_mm_min = rapid;
        const CheckOutcome out = run_check(frames_of(p), nullptr, setup);
        ASSERT_TRUE(out.passed()) << first_violation(*out.checker);
        EXPECT_EQ(out.checker->position(), (GridPoint{0, 0}));
        const InterpConfig cfg = interp_config(setup.clock_hz, {}, rapid);
        // k = 10 for the 1 mm traverse: M 2^10 / S clocks.
        const uint64_t want = ((cfg.feed_modulus << 10) + cfg.rapid_step - 1) / cfg.rapid_step;
        ASSERT_FALSE(out.checker->results()[0].saturated);
        EXPECT_EQ(out.checker->results()[0].clocks, want);
        EXPECT_EQ(out.checker->results()[1].clocks, cfg.feed_modulus / 6000000);
        traverse_clocks[rapid == 2000.0 ? 0 : 1] = out.checker->results()[0].clocks;
      }
      EXPECT_EQ(traverse_clocks[0], 2 * traverse_clocks[1]);
    }
  }
}

TEST(TrajectoryChecker, TotalErrorOfAnInscribedPolygonMatchesTheCircle) {
  const double r_mm = 20.0;
  firststage::Contour circle;
  circle.origin = {r_mm, 0.0};
  circle.segments.push_back(firststage::Segment::arc({0, 0}, r_mm, 0.0, 2 * M_PI));
  circle.element_names = {"circle"};
  tape::Program p;
  const int sides = 64;
  int64_t px = 20000, py = 0;
  for (int k = 1; k <= sides; ++k) {
    const double a = 2 * M_PI * k / sides;
    const int64_t x = std::llround(20000 * std::cos(a)), y = std::llround(20000 * std::sin(a));
    tape::Block b;
    b.n = static_cast<uint32_t>(k);
    b.dx = x - px;
    b.dy = y - py;
    b.feed = 2'000'000;  // 1/F = 30 ms: 30000 clocks at 1 MHz
    p.blocks.push_back(b);
    px = x, py = y;
  }
  CheckSetup setup;
  setup.reader_cps = 1e6;
  setup.tol_mm = 0.1;
  const CheckOutcome out = run_check(frames_of(p), &circle, setup);
  ASSERT_TRUE(out.passed()) << first_violation(*out.checker);
  const TrajectoryChecker& c = *out.checker;
  ASSERT_GT(c.pulses().size(), 1000u);
  double max_e = 0.0;
  for (const PulseSample& s : c.pulses()) {
    const double want = std::fabs(std::hypot(20000.0 + s.position.x, static_cast<double>(s.position.y)) - 20000.0);
    ASSERT_NEAR(s.total_error, want, 1e-3);  // float storage
    max_e = std::max(max_e, want);
  }
  EXPECT_NEAR(c.total_error().max, max_e, kDistanceAccuracy);
  // Sagitta of a 64-gon of radius 20 mm: R (1 - cos(pi/64)) = 24.1 BLU, plus the pulse path.
  EXPECT_GT(c.total_error().max, 23.0);
  EXPECT_LT(c.total_error().max, 25.5);
}

// Hand-made outputs: one block N7 moving (+3, 0) at a saturated feed (one iteration per clock).
class SyntheticRun : public ::testing::Test {
 protected:
  SyntheticRun() {
    tape::Block b;
    b.n = 7;
    b.dx = 3;
    b.feed = 60'000'000'000;  // = M at 1 MHz: saturated
    blocks_ = lay_out(tape::Program{{b}, false});
    options_.feed_modulus = 60'000'000'000;
  }
  // Outputs after reset, then the listed clocks (busy from clock 1).
  void play(const std::vector<InterpOutputs>& clocks) {
    checker_ = std::make_unique<TrajectoryChecker>(blocks_, nullptr, options_);
    checker_->observe(0, InterpOutputs{});
    for (size_t c = 0; c < clocks.size(); ++c) checker_->observe(c + 1, clocks[c]);
    checker_->finish(clocks.empty() ? InterpOutputs{} : clocks.back());
  }
  static InterpOutputs busy(int64_t x, bool step = false) {
    InterpOutputs o;
    o.busy = true;
    o.feed_saturated = true;  // F << k >= M
    o.block_n = 7;
    o.dir_x = o.dir_y = true;
    o.pos_x = x;
    o.step_x = step;
    return o;
  }
  static InterpOutputs idle_done(int64_t x) {
    InterpOutputs o;
    o.block_n = 7;
    o.pos_x = x;
    o.done = true;
    return o;
  }
  Rule first_rule() const { return checker_->violations().front().rule; }
  uint64_t first_cycle() const { return checker_->violations().front().cycle; }

  std::vector<ProgrammedBlock> blocks_;
  CheckerOptions options_;
  std::unique_ptr<TrajectoryChecker> checker_;
};

// k = 2: 4 iterations at clocks L+1..L+4, pulses floor((2 + 3j)/4) = 1, 2, 2, 3 (j=1..4):
// pulses at iterations 1, 2 and 4; the block lasts 2^k + 1 = 5 clocks (busy falls at L+5).
TEST_F(SyntheticRun, DocumentedSequencePasses) {
  play({busy(0), busy(1, true), busy(2, true), busy(2), busy(3, true), idle_done(3)});
  EXPECT_EQ(checker_->violation_count(), 0u) << checker_->violations().front().detail;
}

TEST_F(SyntheticRun, LatePulseIsReportedWhereItWasDue) {
  play({busy(0), busy(1, true), busy(1), busy(2, true), busy(3, true), idle_done(3)});
  ASSERT_GT(checker_->violation_count(), 0u);
  EXPECT_EQ(first_rule(), Rule::kSchedule);
  EXPECT_EQ(first_cycle(), 3u);
}

TEST_F(SyntheticRun, MissingPulseFailsScheduleAndEndpoint) {
  play({busy(0), busy(1, true), busy(2, true), busy(2), busy(2), idle_done(2)});
  ASSERT_GE(checker_->violations().size(), 2u);
  EXPECT_EQ(first_rule(), Rule::kSchedule);
  EXPECT_EQ(first_cycle(), 5u);
  EXPECT_EQ(checker_->violations()[1].rule, Rule::kEndpoint);
  EXPECT_EQ(checker_->violations()[1].cycle, 6u);
}

TEST_F(SyntheticRun, CounterMovingWithoutPulse) {
  play({busy(0), busy(1, true), busy(3, true), busy(3), busy(4, true), idle_done(4)});
  EXPECT_EQ(first_rule(), Rule::kCounter);
  EXPECT_EQ(first_cycle(), 3u);
}

TEST_F(SyntheticRun, WrongDirectionOutput) {
  InterpOutputs flipped = busy(1);
  flipped.dir_x = false;
  play({busy(0), busy(1, true), flipped});
  EXPECT_EQ(first_rule(), Rule::kDirection);
  EXPECT_EQ(first_cycle(), 3u);
}

TEST_F(SyntheticRun, SaturationFlagMustMatchTheDocumentedRule) {
  InterpOutputs o = busy(1, true);
  o.feed_saturated = false;
  play({busy(0), o});
  EXPECT_EQ(first_rule(), Rule::kDuration);
  EXPECT_EQ(first_cycle(), 2u);
}

TEST_F(SyntheticRun, PulseWhileIdle) {
  InterpOutputs o;
  o.step_y = true;
  o.dir_y = true;
  o.pos_y = 1;
  play({o});
  EXPECT_EQ(first_rule(), Rule::kIdlePulse);
}

TEST_F(SyntheticRun, RunThatNeverEnds) {
  play({busy(0), busy(1, true), busy(2, true)});
  EXPECT_EQ(checker_->violations().back().rule, Rule::kComplete);
}

TEST_F(SyntheticRun, PulseOffThePathBreaksTheBound) {
  options_.schedule = false;  // the bound rule alone
  InterpOutputs o = busy(1, true);
  o.step_y = true;
  o.pos_y = 1;
  play({busy(0), o});
  ASSERT_GT(checker_->violation_count(), 0u);
  // (1, 1) is 1 BLU from the segment (0,0)-(3,0): over the bound 1/2; a Y pulse is also
  // more than the block's 0 on Y.
  bool bound = false;
  for (const Violation& v : checker_->violations()) bound |= v.rule == Rule::kPathBound;
  EXPECT_TRUE(bound);
}

}  // namespace
}  // namespace ncinterp::checker

namespace ncinterp::checker {
namespace {

// Traverses come from the tape, nothing is guessed (the minimal case: a traverse
// back along the finished line was measured as a cut, and a cut off the contour could pass
// as a traverse). The same geometry plays on the golden model with the middle block a G00
// and a G01, and the checker judges: the G00 block not against the contour (it lies 5 mm
// off), the G01 blocks against it, and a G01 block that strays is a failure even where it
// runs along a traverse of the input.
TEST(TrajectoryChecker, TraversesAreTheTapesG00BlocksAndOnlyThem) {
  // Contour: a line X0 -> X20 cut, then the input's traverse back to X0 at Y5, and a cut
  // X0 -> X20 at Y5.
  firststage::Contour c;
  c.origin = {0, 0};
  std::vector<firststage::Segment> segs = {firststage::Segment::line({0, 0}, {20, 0}),
                                           firststage::Segment::line({20, 0}, {0, 5}),
                                           firststage::Segment::line({0, 5}, {20, 5})};
  segs[1].rapid = true;
  c = firststage::contour_from_segments("t.nc", {0, 0}, segs);
  const InterpConfig cfg = interp_config(1e6);
  const auto judge = [&](tape::Motion middle) {
    tape::Program p;
    p.blocks = {{1, tape::Motion::kLine, 20000, 0, 0, 0, 50000},
                {2, middle, -20000, 5000, 0, 0, tape::is_rapid(middle) ? 0u : 50000u},
                {3, tape::Motion::kLine, 20000, 0, 0, 0, 50000}};
    const std::vector<InterpOutputs> trace = test::golden_trace(frames_of(p), cfg, 1);
    ReferenceOptions ro;
    ro.blu_mm = 0.001;
    ReferenceContour ref(c, ro);
    CheckerOptions co = options_for(cfg);
    auto checker = std::make_unique<TrajectoryChecker>(lay_out(p), &ref, co);
    for (size_t k = 0; k < trace.size(); ++k) checker->observe(k, trace[k]);
    checker->finish(trace.back());
    checker->check_tolerance(10.0);
    return checker;
  };
  const auto as_g00 = judge(tape::Motion::kRapid);
  EXPECT_EQ(as_g00->violation_count(), 0u) << first_violation(*as_g00);
  EXPECT_TRUE(as_g00->results()[1].rapid);
  EXPECT_EQ(as_g00->results()[1].total.count, 0u);
  EXPECT_GT(as_g00->results()[1].path.count, 0u);  // its interpolator error is measured
  EXPECT_LE(as_g00->total_error().max, 1.0);
  // The same block as G01 is a cut 2.5 mm (2500 BLU) off the contour at its middle.
  const auto as_g01 = judge(tape::Motion::kLine);
  EXPECT_FALSE(as_g01->results()[1].rapid);
  EXPECT_GT(as_g01->results()[1].total.max, 2000.0);
  ASSERT_FALSE(as_g01->violations().empty());
  EXPECT_EQ(as_g01->violations().front().rule, Rule::kTotalError);
  EXPECT_EQ(as_g01->violations().front().n, 2u);
}

}  // namespace
}  // namespace ncinterp::checker
