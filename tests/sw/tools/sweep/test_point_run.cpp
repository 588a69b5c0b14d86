// A design point's measurement setup: the parameters the tools take from a point, here the
// configuration CircleMode, which the first stage and the golden model follow.
#include <gtest/gtest.h>

#include "inputs/contour_inputs.h"
#include "point_run.h"
#include "sweep_test_support.h"

namespace ncinterp::sweep {
namespace {

// The 50 mm circle, programmed as arcs: a lines-only point (CircleMode=0) has no circle
// mode, so its first stage cuts the arcs as chords, a longer tape the golden model plays
// within the tolerance; the point with circle mode plays the quadrant arcs.
TEST(PointRun, ALinesOnlyPointCutsArcsAsChordsAndPlaysThemWithinTheTolerance) {
  const std::string path = test::example("contours/circle_r50.json");
  PointSetup setup;
  setup.inputs = {{path, firststage::read_contour(path, firststage::InputOptions{})}};
  setup.synthesis = false;
  setup.rtl = false;
  setup.measure.first_stage.tol_mm = 0.01;
  setup.measure.first_stage.arcs_circle = true;
  setup.measure.first_stage.feed_mm_min = 20000;
  setup.measure.reader_cps = 100000;
  const PointResult lines = run_point({{kIncWidth, 16}, {kCircleMode, 0}}, "lines", setup);
  const PointResult arcs = run_point({{kIncWidth, 16}, {kCircleMode, 1}}, "arcs", setup);
  for (const PointResult* r : {&lines, &arcs}) {
    const InputResult& in = r->row.inputs.at(0);
    ASSERT_TRUE(in.measured()) << r->key << ": " << in.failure;
    EXPECT_EQ(in.violations, 0u) << r->key << ": " << in.first_violation;
    EXPECT_LE(in.total_error_max_mm, 0.01) << r->key;
  }
  EXPECT_EQ(arcs.row.inputs[0].blocks, 4u) << "four quadrant arcs";
  EXPECT_GT(lines.row.inputs[0].blocks, 50u) << "chords";
  EXPECT_GT(lines.row.inputs[0].frames, 10 * arcs.row.inputs[0].frames);
}

}  // namespace
}  // namespace ncinterp::sweep
