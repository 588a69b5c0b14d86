// The RTL verilated with other parameters in lock step with the golden model configured
// alike. The Heavy tests build real variants (W = 8 parallel, and W = 12 at a 0.01 mm BLU
// serial: about 20 s each the first time; the build trees are kept under the test's build directory, so reruns only check
// they are up to date).
#include <gtest/gtest.h>

#include "inputs/contour_inputs.h"
#include "rtl_variant.h"
#include "scratch_dir_test.h"
#include "sweep_defaults.h"
#include "sweep_test_support.h"
#include "tape_measurement.h"

namespace ncinterp::sweep {
namespace {

using RtlVariantBuild = ncinterp::test::ScratchDirTest;

// The variant tests' setting: the 50 mm circle's tape at W (chords, or arc blocks), measured
// on the golden model by the sweep's own code at a fast reader and a high feed.
class RtlVariantHeavy : public ncinterp::test::ScratchDirTest {
 protected:
  RtlVariantSetup setup() const {
    RtlVariantSetup s = default_rtl_variant_setup(std::string(NCINTERP_SWEEP_TEST_WORK) + "/variant-cache");
    s.reader_cps = 100000;
    return s;
  }
  InputResult circle_tape(unsigned width, bool arcs, const std::string& tape, double blu_mm = 0.001,
                          Arch arch = Arch::kParallel) {
    MeasureSetup m;
    m.first_stage.feed_mm_min = 20000;
    m.first_stage.arcs_circle = arcs;
    m.first_stage.blu_mm = blu_mm;
    m.first_stage.tol_mm = 5 * blu_mm;  // room for the chords beside the interpolator's error
    m.arch = arch;
    m.reader_cps = setup().reader_cps;
    const std::string input = test::example("contours/circle_r50.json");
    const SweepInput circle{input, firststage::read_contour(input, firststage::InputOptions{})};
    return measure_input(circle, width, m, tape);
  }
};

TEST_F(RtlVariantHeavy, BuildsAtW8AndMatchesTheGoldenModelOnEveryClock) {
  const std::string tape = path("circle_w8.tape");
  const InputResult in = circle_tape(8, false, tape);
  ASSERT_TRUE(in.measured()) << in.failure;

  const RtlResult r = run_rtl_variant(setup(), RtlVariant{8, 3, Arch::kParallel}, {tape});
  EXPECT_TRUE(r.ran);
  EXPECT_TRUE(r.all_match) << r.summary;
  // The variant ran as many clocks as the golden model under the checker: the same run.
  EXPECT_EQ(r.summary, "match on 1 tapes, " + std::to_string(in.cycles) + " clocks");
}

// The serial arch (interp_top's BitSerial) on the 50 mm circle programmed as arcs at W = 12
// and a BLU of 0.01 mm, in lock step with the golden model configured alike. Its arcs take
// 2PN clocks to prepare: the run is longer than the checker's run of the same tape in
// the parallel arch, which shows that the variant is the serial one.
TEST_F(RtlVariantHeavy, SerialArchAtAnotherBluMatchesTheGoldenModelOnEveryClock) {
  const std::string tape = path("circle_arcs_w12.tape");
  const InputResult in = circle_tape(12, true, tape, 0.01, Arch::kParallel);
  ASSERT_TRUE(in.measured()) << in.failure;

  const RtlResult r = run_rtl_variant(setup(), RtlVariant{12, 2, Arch::kSerial}, {tape});
  EXPECT_TRUE(r.ran);
  EXPECT_TRUE(r.all_match) << r.summary;
  const std::string prefix = "match on 1 tapes, ";
  ASSERT_EQ(r.summary.rfind(prefix, 0), 0u) << r.summary;
  EXPECT_GT(std::stoull(r.summary.substr(prefix.size())), in.cycles) << r.summary;
}

TEST_F(RtlVariantBuild, ABrokenRtlFileGivesTheBuildFailureWithVerilatorsReason) {
  RtlVariantSetup s = default_rtl_variant_setup(dir_.string());
  s.rtl_sources = {test::fixture("broken_interp_top.sv")};
  const RtlResult r = run_rtl_variant(s, RtlVariant{8, 3, Arch::kSerial}, {"unused.tape"});
  EXPECT_FALSE(r.ran);
  EXPECT_FALSE(r.all_match);
  EXPECT_EQ(r.summary.rfind("configuring the W=8 D=3 serial variant failed", 0), 0u) << r.summary;
  EXPECT_NE(r.summary.find("%Error"), std::string::npos) << r.summary;
}

TEST_F(RtlVariantBuild, NoTapeNoRun) {
  const RtlResult r = run_rtl_variant(default_rtl_variant_setup(dir_.string()), RtlVariant{8, 3, Arch::kSerial}, {});
  EXPECT_FALSE(r.ran);
  EXPECT_EQ(r.summary, "not run: no tape at this width");
}

}  // namespace
}  // namespace ncinterp::sweep
