// End-to-end regression (CI): the example contours through the first stage, the tape, the
// golden model AND the verilated RTL, each judged by the trajectory checker, plus the
// lock-step scoreboard on the same tape. Every chord method, a cutter-offset case, the arc
// modes, and a short run of random contours. Sized to run in well under a minute per
// core: feeds are high (about a second of machine time per part) and the reader fast.
// The long version is the soak (bench/soak, docs/verification.md).
#include <gtest/gtest.h>

#include <cstdlib>
#include <iostream>
#include <string>
#include <vector>

#include "random_contour.h"
#include "regression_support.h"
#ifdef NCINTERP_TEST_HAS_COSIM
#include "check_report.h"
#include "lockstep.h"
#endif

namespace ncinterp::regression {
namespace {

struct Example {
  std::string name;  // test name
  std::string file;  // examples/contours/<file>
  int method = 3;
  bool arcs_circle = false;
  double cutter_radius_mm = 0.0;
  bool side_left = true;
  double feed_mm_min = 20000;
};

void PrintTo(const Example& e, std::ostream* os) { *os << e.name; }

Case case_of(const Example& e) {
  Case c;
  c.name = e.name;
  c.contour = firststage::read_contour(example_path(e.file), {});
  c.first_stage.method = e.method;
  c.first_stage.tol_mm = 0.01;
  c.first_stage.arcs_circle = e.arcs_circle;
  c.first_stage.cutter_radius_mm = e.cutter_radius_mm;
  c.first_stage.side_left = e.side_left;
  c.first_stage.feed_mm_min = e.feed_mm_min;
  c.check.clock_hz = 1e6;
  c.check.reader_cps = 1e5;
  return c;
}

// Checks the case on `engine` and expects a clean pass; returns the check's report.
nlohmann::json expect_clean_check(const Case& c, EngineKind engine) {
  Case run = c;
  run.check.engine = engine;
  const checker::CheckOutcome out = run_case(run);
  std::cout << describe(run, out);
  EXPECT_TRUE(out.passed()) << describe(run, out);
  const checker::TrajectoryChecker& k = *out.checker;
  EXPECT_EQ(k.results().size(), out.program.blocks.size());
  EXPECT_TRUE(out.run.last.done);
  if (c.first_stage.arcs_circle) {
    // Arcs are programmed as arcs: the total error is the circle DDA's (<= 1 BLU, docs/
    // circle-dda.md) plus the rounding of the arc ends to the grid (<= 1/2 BLU).
    EXPECT_LE(k.total_error().max, 1.5);
  } else {
    // The measurement sees the chords: the total error is mostly the chord deviation.
    EXPECT_GT(k.total_error().max, k.path_error().max);
  }
  EXPECT_LE(k.total_error().max, out.tol_blu);
  for (const checker::BlockResult& r : k.results()) EXPECT_LE(r.path.max, r.bound + 1e-9);
  return checker::check_report_json(out, {"", "", run.check});
}

class ExampleRegression : public ::testing::TestWithParam<Example> {};

TEST_P(ExampleRegression, GoldenWithinTolerance) {
  expect_clean_check(case_of(GetParam()), EngineKind::kGolden);
}

TEST_P(ExampleRegression, RtlWithinTolerance) {
  ASSERT_TRUE(checker::rtl_available()) << "NOT RUN: no verilated RTL in this build";
  const Case c = case_of(GetParam());
  expect_clean_check(c, EngineKind::kRtl);
}

TEST_P(ExampleRegression, CosimClean) {
#ifndef NCINTERP_TEST_HAS_COSIM
  FAIL() << "NOT RUN: no cosim library in this build";
#else
  const Case c = case_of(GetParam());
  cosim::Options o;
  o.config = interp_config(c.check.clock_hz, firststage::tape_format(c.first_stage));
  o.cycles_per_frame = FrameSource::cycles_per_frame_for(c.check.clock_hz, c.check.reader_cps);
  const cosim::Result r = cosim::run_lockstep(make_tape(c), o);
  ASSERT_FALSE(r.mismatch) << cosim::describe(*r.mismatch);
  EXPECT_EQ(r.end, cosim::Result::End::kDone);
#endif
}

// With the feed ramp (500 mm/s^2, every block from rest to rest) each example plays in lock
// step on both archs, with the pulses per axis and direction and the end position of the
// run without ramps, only later; the checker's rules with the ramp (the DDA's order of
// pulses in every block, the acceleration limit) hold on the golden run. About 13 s an
// example, so CI runs one of each kind (chords of each contour, arcs, a cutter);
// NCINTERP_REGRESSION_ALL=1 build/tests/sw/tools/regression/test_regression
// --gtest_filter='*Ramped*' runs every example.
class RampedRegression : public ::testing::TestWithParam<Example> {};

TEST_P(RampedRegression, KeepsThePulsesOnBothArchs) {
#ifndef NCINTERP_TEST_HAS_COSIM
  FAIL() << "NOT RUN: no cosim library in this build";
#else
  Case c = case_of(GetParam());
  constexpr double kAccel = 500.0;
  c.first_stage.accel_mm_s2 = kAccel;  // taped for the limit, as `tape --accel` does
  for (Arch arch : {Arch::kSerial, Arch::kParallel}) {
    SCOPED_TRACE(arch_name(arch));
    cosim::Options o;
    o.config = interp_config(c.check.clock_hz, firststage::tape_format(c.first_stage));
    o.config.arch = arch;
    o.cycles_per_frame = FrameSource::cycles_per_frame_for(c.check.clock_hz, c.check.reader_cps);
    const std::vector<uint8_t> tape = make_tape(c);
    const cosim::Result plain = cosim::run_lockstep(tape, o);
    o.config = interp_config(c.check.clock_hz, firststage::tape_format(c.first_stage),
                             kDefaultRapidMmMin, kAccel);
    o.config.arch = arch;
    const cosim::Result ramped = cosim::run_lockstep(tape, o);
    ASSERT_FALSE(ramped.mismatch) << cosim::describe(*ramped.mismatch);
    ASSERT_EQ(plain.end, cosim::Result::End::kDone);
    ASSERT_EQ(ramped.end, cosim::Result::End::kDone);
    for (int axis = 0; axis < 2; ++axis)
      for (int dir = 0; dir < 2; ++dir) EXPECT_EQ(ramped.stats.pulses[axis][dir], plain.stats.pulses[axis][dir]);
    EXPECT_EQ(ramped.last.pos_x, plain.last.pos_x);
    EXPECT_EQ(ramped.last.pos_y, plain.last.pos_y);
    EXPECT_GT(ramped.cycles, plain.cycles);
  }
  c.check.accel_mm_s2 = kAccel;
  // The feed plan (ncinterp tape --accel) foretells the played time from the first load on,
  // less the clocks the reader kept the interpolator waiting: its trapezoids are the
  // ramp's, within GoldenRamp.EachBlockLastsItsIdealTrapezoidWithinAFewClocks's bound.
  const nlohmann::json report = expect_clean_check(c, EngineKind::kGolden);
  const double clock_hz = report["clock_hz"], blocks = report["blocks"], gaps = report["gap_clocks"];
  const double played = report["feed_plan"]["played_seconds"].get<double>() - gaps / clock_hz;
  EXPECT_NEAR(played, report["feed_plan"]["planned_seconds"].get<double>(), 1e-3 * played + 20 * blocks / clock_hz);
#endif
}

const Example kExamples[] = {
    {"circle_m1", "circle_r50.json", 1},
    {"circle_m2", "circle_r50.json", 2},
    {"circle_m3", "circle_r50.json", 3},
    {"circle_arcs", "circle_r50.json", 3, true},
    {"table_m1", "reference_table.json", 1},
    {"table_m2", "reference_table.json", 2},
    {"table_m3", "reference_table.json", 3},
    {"naca_selig_m1", "naca2412_selig.dat", 1},
    {"naca_selig_m2", "naca2412_selig.dat", 2},
    {"naca_lednicer_m3", "naca2412_lednicer.dat", 3},
    {"part_m1", "part.nc", 1},
    {"part_m2", "part.nc", 2},
    {"part_m3", "part.nc", 3},
    {"part_arcs", "part.nc", 3, true},
    {"part_cutter_right", "part.nc", 3, false, 3.0, false},
    {"naca_cutter_right", "naca2412_selig.dat", 3, false, 2.0, false},
};

INSTANTIATE_TEST_SUITE_P(Examples, ExampleRegression, ::testing::ValuesIn(kExamples),
                         [](const ::testing::TestParamInfo<Example>& i) { return i.param.name; });

std::vector<Example> ramped_examples() {
  const char* all = std::getenv("NCINTERP_REGRESSION_ALL");
  if (all && std::string(all) == "1") return {std::begin(kExamples), std::end(kExamples)};
  std::vector<Example> some;
  for (const Example& e : kExamples)
    for (const char* name : {"circle_m1", "table_m3", "naca_lednicer_m3", "part_arcs", "part_cutter_right"})
      if (e.name == name) some.push_back(e);
  return some;
}

INSTANTIATE_TEST_SUITE_P(Examples, RampedRegression, ::testing::ValuesIn(ramped_examples()),
                         [](const ::testing::TestParamInfo<Example>& i) { return i.param.name; });

// A short run of the soak's random contours, golden and RTL (the soak runs hundreds).
class RandomRegression : public ::testing::TestWithParam<uint64_t> {};

TEST_P(RandomRegression, GoldenAndRtlWithinTolerance) {
  RandomCaseLimits limits;
  limits.seconds = 0.3;
  Case c = random_case(GetParam(), limits);
  c.check.engine = EngineKind::kGolden;
  const checker::CheckOutcome g = run_case(c);
  EXPECT_TRUE(g.passed()) << describe(c, g);
  if (!checker::rtl_available() || c.first_stage.width != 16) return;  // RTL: W = 16 only
  c.check.engine = EngineKind::kRtl;
  const checker::CheckOutcome r = run_case(c);
  EXPECT_TRUE(r.passed()) << describe(c, r);
  EXPECT_EQ(r.checker->total_error().max, g.checker->total_error().max);
}

// Fixed seeds (not chosen by their outcome): twelve contours of every shape, method,
// tolerance, register width and cutter setting the soak draws from.
INSTANTIATE_TEST_SUITE_P(Seeds, RandomRegression, ::testing::Range<uint64_t>(1000, 1012));

}  // namespace
}  // namespace ncinterp::regression
