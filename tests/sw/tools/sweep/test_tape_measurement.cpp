// What a width does to an input's tape and to the measured errors (first stage, golden
// model at W, checker).
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>

#include "inputs/contour_inputs.h"
#include "scratch_dir_test.h"
#include "sweep_test_support.h"
#include "tape_measurement.h"

namespace ncinterp::sweep {
namespace {

SweepInput circle() {
  const std::string path = test::example("contours/circle_r50.json");
  return {path, firststage::read_contour(path, firststage::InputOptions{})};
}

MeasureSetup fast_setup() {
  MeasureSetup s;
  s.first_stage.tol_mm = 0.01;
  s.first_stage.feed_mm_min = 20000;  // about a second of machine time for the circle
  s.reader_cps = 100000;
  return s;
}

// Narrow registers force shorter blocks (the paper's dy_max): fewer bits, more blocks,
// each within the register; once the register holds the longest chord the tolerance
// allows (about 1.9 mm = 1900 BLU on this circle: W = 11), W no longer matters.
TEST(TapeMeasurement, BlocksFallAsTheRegisterWidensUntilTheToleranceLimitsTheChord) {
  const SweepInput in = circle();
  const MeasureSetup setup = fast_setup();
  std::vector<size_t> blocks;
  for (unsigned w = 7; w <= 14; ++w) {
    const WidthTape t = tape_at_width(in, w, setup);
    const int64_t limit = (int64_t{1} << w) - 1;
    int64_t biggest = 0;
    for (const tape::Block& b : t.program.blocks) biggest = std::max({biggest, static_cast<int64_t>(std::llabs(b.dx)), static_cast<int64_t>(std::llabs(b.dy))});
    EXPECT_LE(biggest, limit) << "W " << w;
    if (w == 7) EXPECT_GT(biggest, limit / 2) << "at W 7 the register, not delta, limits the blocks";
    blocks.push_back(t.program.blocks.size());
  }
  for (size_t i = 1; i < blocks.size(); ++i) EXPECT_LE(blocks[i], blocks[i - 1]) << "W " << 7 + i;
  EXPECT_GT(blocks.front(), 8 * blocks.back());
  EXPECT_EQ(blocks[blocks.size() - 2], blocks.back()) << "W 13 and 14: the tolerance limits the chords";
}

using TapeFile = ncinterp::test::ScratchDirTest;

// In the parallel arch, where the fast setup's feed leaves blocks timed (not saturated).
TEST_F(TapeFile, GoldenModelAtWidthPlaysTheTapeWithinTheBounds) {
  MeasureSetup setup = fast_setup();
  setup.arch = Arch::kParallel;
  const std::string tape = path("circle_w10.tape");
  const InputResult r = measure_input(circle(), 10, setup, tape);
  ASSERT_TRUE(r.measured()) << r.failure;
  EXPECT_EQ(r.violations, 0u) << r.first_violation;
  EXPECT_GT(r.blocks, 200u);
  EXPECT_GT(r.frames, 20 * r.blocks);
  EXPECT_GT(r.path_error_max_blu, 0.3);
  EXPECT_LE(r.path_error_max_blu, 0.7072);  // sqrt(2)/2 BLU, docs/interpolator.md 5.6
  EXPECT_GT(r.total_error_max_mm, 0.0);
  EXPECT_LE(r.total_error_max_mm, setup.first_stage.tol_mm);
  EXPECT_GT(r.feed_error_worst, 0.0);  // ceil(M/F): never early
  EXPECT_LT(r.feed_error_worst, 1e-3);
  EXPECT_GT(r.cycles, 500000u);
  EXPECT_EQ(r.tape_path, tape);
  EXPECT_EQ(std::filesystem::file_size(tape), r.frames);
}

TEST(TapeMeasurement, AnInputTheFirstStageRefusesKeepsTheReason) {
  MeasureSetup setup = fast_setup();
  setup.first_stage.tol_mm = 0.0015;  // leaves less than 1 BLU after the interpolator's budget
  const InputResult r = measure_input(circle(), 12, setup);
  EXPECT_FALSE(r.measured());
  EXPECT_EQ(r.failure.rfind("first stage: --tol leaves less than 1 BLU", 0), 0u) << r.failure;
  EXPECT_EQ(r.blocks, 0u);
}

}  // namespace
}  // namespace ncinterp::sweep
