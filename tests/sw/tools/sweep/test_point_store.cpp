// Plan, run-one and collect: one point at a time in any order gives the tables of the
// whole grid; a point with a result file is never measured again; a failing point keeps
// its reason through its result file.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>

#include "grid_report.h"
#include "inputs/contour_inputs.h"
#include "point_store.h"
#include "scratch_dir_test.h"
#include "sweep_run.h"
#include "sweep_test_support.h"
#include "synth_cache.h"

namespace ncinterp::sweep {
namespace {

// The circle at a high feed and a quick reader: about a second of machine time per point.
PointSetup fast_setup(const std::string& dir) {
  PointSetup s;
  const std::string path = test::example("contours/circle_r50.json");
  s.inputs.push_back({path, firststage::read_contour(path, firststage::InputOptions{})});
  s.measure.first_stage.feed_mm_min = 20000;
  s.measure.reader_cps = 100000;
  s.synthesis = false;
  s.rtl = false;
  s.tape_dir = dir + "/tapes";
  return s;
}

// IncWidth 10, 11 x PosWidth 16, 32: at 16 bits the counters (+-32767 BLU) cannot hold the
// circle's 100 mm (100000 BLU), so those points fail the check.
Plan small_plan(const PointSetup& s) {
  Plan plan;
  plan.axes = {"IncWidth", "PosWidth"};
  plan.inputs = {s.inputs.front().path};
  const std::string hash = setup_hash(s, {"test"}, {});
  for (const DesignPoint& p : expand_grid({{"IncWidth", {10, 11}}, {"PosWidth", {16, 32}}}))
    plan.points.push_back({p, point_key(p, hash)});
  return plan;
}

std::string collected_csv(const std::string& dir, const Plan& plan) {
  return to_csv(grid_table(collect_results(dir, plan), plan.axes));
}

using PointStore = ncinterp::test::ScratchDirTest;

TEST_F(PointStore, KeysFollowThePointAndTheSetup) {
  const PointSetup s = fast_setup(dir_.string());
  const Plan plan = small_plan(s);
  for (size_t i = 0; i < plan.points.size(); ++i)
    for (size_t j = 0; j < i; ++j) EXPECT_NE(plan.points[i].key, plan.points[j].key);
  EXPECT_EQ(small_plan(s).points[0].key, plan.points[0].key);  // same point, same key
  EXPECT_NE(point_key(plan.points[0].point, setup_hash(s, {"other"}, {})), plan.points[0].key);
}

TEST_F(PointStore, RunOneInAnyOrderCollectsToTheSameTables) {
  const std::string a = path("a"), b = path("b");
  const PointSetup s = fast_setup(dir_.string());
  const Plan plan = small_plan(s);
  write_plan(a, plan);
  write_plan(b, plan);
  EXPECT_EQ(read_plan(a).points.size(), 4u);
  for (const PlannedPoint& p : plan.points) EXPECT_TRUE(run_one_point(plan, a, s, p.key));
  for (auto it = plan.points.rbegin(); it != plan.points.rend(); ++it) EXPECT_TRUE(run_one_point(plan, b, s, it->key));
  const std::string csv = collected_csv(a, plan);
  EXPECT_EQ(collected_csv(b, plan), csv);
  EXPECT_NE(csv.find("\n10,16,"), std::string::npos) << csv;  // rows in grid order
  EXPECT_LT(csv.find("\n10,16,"), csv.find("\n11,32,"));
  EXPECT_THROW(run_one_point(plan, a, s, "0000000000000000"), std::invalid_argument);
}

TEST_F(PointStore, AMeasuredPointIsNeverMeasuredAgain) {
  const std::string d = path("c");
  const PointSetup s = fast_setup(dir_.string());
  const Plan plan = small_plan(s);
  EXPECT_EQ(run_missing_points(plan, d, s, 2), 4u);
  EXPECT_EQ(run_missing_points(plan, d, s, 2), 0u);
  EXPECT_FALSE(run_one_point(plan, d, s, plan.points[1].key));
  // The stored result is what collect reads: change it and the table follows, no rerun.
  std::optional<PointResult> r = load_result(d, plan.points[1].key);
  ASSERT_TRUE(r);
  r->row.inputs[0].blocks = 424242;
  store_result(d, *r);
  EXPECT_EQ(run_missing_points(plan, d, s, 2), 0u);
  EXPECT_NE(collected_csv(d, plan).find("424242"), std::string::npos);
  // A result file that cannot be read is measured again.
  std::ofstream(result_path(d, plan.points[2].key)) << "{ truncated";
  EXPECT_EQ(run_missing_points(plan, d, s, 1), 1u);
}

TEST_F(PointStore, AFailingPointKeepsItsReasonAndAMissingOneSaysSo) {
  const std::string d = path("d");
  const PointSetup s = fast_setup(dir_.string());
  const Plan plan = small_plan(s);
  ASSERT_TRUE(run_one_point(plan, d, s, plan.points[0].key));  // IncWidth 10, PosWidth 16
  ASSERT_TRUE(run_one_point(plan, d, s, plan.points[1].key));  // IncWidth 10, PosWidth 32
  const Table t = grid_table(collect_results(d, plan), plan.axes);
  const size_t check = t.column("check");
  EXPECT_EQ(t.rows[0][check].rfind("FAIL circle_r50.json: ", 0), 0u) << t.rows[0][check];
  EXPECT_EQ(t.rows[1][check], "pass");
  EXPECT_EQ(t.rows[2][check], "circle_r50.json: not run: no result file " + plan.points[2].key + ".json");
  EXPECT_EQ(t.rows[0][t.column("cells")], "not run (--no-synth)");
  EXPECT_EQ(t.rows[0][t.column("pos_range_mm")], "32.767");
  EXPECT_EQ(t.rows[1][t.column("max_move_mm")], "1.023");
}

TEST_F(PointStore, ASynthesisFailureSurvivesTheResultFile) {
  const std::string d = path("e");
  PointSetup s = fast_setup(dir_.string());
  s.synthesis = true;
  s.synth.rtl_sources = {test::fixture("broken_interp_top.sv")};
  s.synth.fpga_top = test::fixture("tiny_fpga_top.sv");
  s.synth.work_dir = d + "/work";
  s.synth.cache_dir = d + "/synth";
  s.synth_key = synthesis_key(s.synth);
  Plan plan;
  plan.axes = {"IncWidth"};
  plan.inputs = {s.inputs.front().path};
  plan.points.push_back({{{"IncWidth", 8}}, point_key({{"IncWidth", 8}}, setup_hash(s, {}, {}))});
  ASSERT_TRUE(run_one_point(plan, d, s, plan.points[0].key));
  const std::optional<PointResult> r = load_result(d, plan.points[0].key);
  ASSERT_TRUE(r);
  EXPECT_EQ(r->row.synth.cells.reason.rfind("yosys synth failed: ", 0), 0u) << r->row.synth.cells.reason;
  EXPECT_EQ(r->row.synth.small_logic_cells.reason.rfind("yosys synth_ice40 (harness) failed: ", 0), 0u);
  EXPECT_GT(r->seconds, 0.0);
}

}  // namespace
}  // namespace ncinterp::sweep
