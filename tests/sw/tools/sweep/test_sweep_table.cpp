// The sweep table: totals only when every input was measured, reasons kept in their
// columns, CSV quoting, Markdown column selection.
#include <gtest/gtest.h>

#include "sweep_table.h"

namespace ncinterp::sweep {
namespace {

InputResult measured(const std::string& name, uint64_t blocks, double path_blu, double total_mm, double feed) {
  InputResult in;
  in.input = "examples/" + name;
  in.blocks = blocks;
  in.frames = 30 * blocks;
  in.path_error_max_blu = path_blu;
  in.total_error_max_mm = total_mm;
  in.feed_error_worst = feed;
  in.cycles = 1000;
  return in;
}

SweepRow row(unsigned w, std::vector<InputResult> inputs) {
  SweepRow r;
  r.width = w;
  r.inputs = std::move(inputs);
  r.synth.cells = Measured::of(6026);
  r.synth.flip_flops = Measured::of(776);
  r.synth.ice40_luts = Measured::absent("yosys not on PATH");
  r.synth.ice40_logic_cells = Measured::absent("too big for the HX8K: 9000 of 7680 logic cells");
  r.synth.fmax_mhz = Measured::absent("too big for the HX8K: 9000 of 7680 logic cells");
  r.rtl.summary = "match on 2 tapes, 2000 clocks";
  return r;
}

TEST(SweepTable, TotalsAndWorstValuesOverEveryInput) {
  const Table t = sweep_table({row(12, {measured("a.json", 10, 0.5, 0.004, -2e-5), measured("b.nc", 5, 0.7, 0.009, 1e-5)})});
  ASSERT_EQ(t.rows.size(), 1u);
  const auto& r = t.rows[0];
  EXPECT_EQ(r[t.column("width")], "12");
  EXPECT_EQ(r[t.column("blocks")], "15");
  EXPECT_EQ(r[t.column("tape_frames")], "450");
  EXPECT_EQ(r[t.column("path_error_max_blu")], "0.7000");
  EXPECT_EQ(r[t.column("total_error_max_mm")], "0.00900");
  EXPECT_EQ(r[t.column("feed_error_worst")], "-2.000e-05");  // the larger magnitude, with its sign
  EXPECT_EQ(r[t.column("cycles")], "2000");
  EXPECT_EQ(r[t.column("check")], "pass");
  EXPECT_EQ(r[t.column("cells")], "6026");
  EXPECT_EQ(r[t.column("ice40_luts")], "yosys not on PATH");
  EXPECT_EQ(r[t.column("fmax_mhz")], "too big for the HX8K: 9000 of 7680 logic cells");
  EXPECT_EQ(r[t.column("blocks a.json")], "10");
  EXPECT_EQ(r[t.column("blocks b.nc")], "5");
}

TEST(SweepTable, AnInputNotMeasuredIsRefusedWithItsReasonOnce) {
  InputResult refused;
  refused.input = "examples/b.nc";
  refused.failure = "first stage: --width must be 2..32 bits";
  const Table t = sweep_table({row(32, {measured("a.json", 10, 0.5, 0.004, 1e-5), refused})});
  const auto& r = t.rows[0];
  // The reason once, in the check column; the totals and worsts say "refused".
  EXPECT_EQ(r[t.column("check")], "b.nc: first stage: --width must be 2..32 bits");
  for (const char* c : {"blocks", "tape_frames", "path_error_max_blu", "total_error_max_mm", "cycles"})
    EXPECT_EQ(r[t.column(c)], "refused") << c;
  EXPECT_EQ(r[t.column("blocks a.json")], "10");
  EXPECT_EQ(r[t.column("blocks b.nc")], "refused");
}

TEST(SweepTable, ACheckerViolationIsNamed) {
  InputResult bad = measured("a.json", 10, 0.5, 0.02, 1e-5);
  bad.violations = 3;
  bad.first_violation = "tolerance at block N4: 0.02 mm";
  const Table t = sweep_table({row(9, {bad})});
  EXPECT_EQ(t.rows[0][t.column("check")], "FAIL a.json: 3 violation(s), first tolerance at block N4: 0.02 mm");
}

TEST(SweepTable, CsvQuotesCellsWithCommasAndQuotes) {
  Table t;
  t.header = {"width", "note"};
  t.rows = {{"8", "match on 1 tapes, 5 clocks"}, {"9", "say \"no\""}, {"10", "plain"}};
  EXPECT_EQ(to_csv(t), "width,note\n8,\"match on 1 tapes, 5 clocks\"\n9,\"say \"\"no\"\"\"\n10,plain\n");
}

TEST(SweepTable, MarkdownTakesTheNamedColumnsInOrder) {
  Table t;
  t.header = {"width", "a", "b"};
  t.rows = {{"8", "x|y", "z"}};
  EXPECT_EQ(to_markdown(t, {"b", "width"}), "| b | width |\n|---|---|\n| z | 8 |\n");
  EXPECT_EQ(to_markdown(t), "| width | a | b |\n|---|---|---|\n| 8 | x\\|y | z |\n");
  EXPECT_THROW(to_markdown(t, {"nope"}), std::out_of_range);
}

}  // namespace
}  // namespace ncinterp::sweep
