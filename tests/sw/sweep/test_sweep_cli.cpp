// `ncinterp sweep` from the command line: a small range end to end, bad options, a tool
// missing from PATH stated in its columns.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <sstream>

#include "subprocess.h"
#include "sweep_test_support.h"

namespace ncinterp::sweep {
namespace {

std::vector<std::vector<std::string>> csv_rows(const std::string& text) {
  std::vector<std::vector<std::string>> rows;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);) {
    std::vector<std::string> cells;
    std::string cell;
    bool quoted = false;
    for (char c : line) {
      if (c == '"') quoted = !quoted;
      else if (c == ',' && !quoted) cells.push_back(cell), cell.clear();
      else cell += c;
    }
    cells.push_back(cell);
    rows.push_back(cells);
  }
  return rows;
}

std::string at(const std::vector<std::vector<std::string>>& rows, size_t row, const std::string& column) {
  const auto& h = rows.at(0);
  const size_t c = static_cast<size_t>(std::find(h.begin(), h.end(), column) - h.begin());
  return c < h.size() ? rows.at(row).at(c) : "(no column " + column + ")";
}

TEST(SweepCli, SmallRangeWritesOneRowPerWidthAndThePlot) {
  const std::string dir = test::fresh_dir();
  const test::CommandResult r = test::run_ncinterp(
      "sweep " + test::example("contours/circle_r50.json") + " --widths 10:11 --feed 20000 --reader-cps 100000 --jobs 2" +
      " --no-synth --no-rtl --cache " + dir + " --csv " + dir + "/s.csv --svg " + dir + "/s.svg --markdown " + dir +
      "/s.md");
  ASSERT_EQ(r.exit_code, 0) << r.output;
  const auto rows = csv_rows(read_text_file(dir + "/s.csv"));
  ASSERT_EQ(rows.size(), 3u);
  EXPECT_EQ(at(rows, 1, "width"), "10");
  EXPECT_EQ(at(rows, 2, "width"), "11");
  EXPECT_GT(std::stoul(at(rows, 1, "blocks")), std::stoul(at(rows, 2, "blocks")));
  EXPECT_EQ(at(rows, 1, "blocks circle_r50.json"), at(rows, 1, "blocks"));
  for (size_t i : {1, 2}) {
    EXPECT_EQ(at(rows, i, "check"), "pass");
    EXPECT_LE(std::stod(at(rows, i, "total_error_max_mm")), 0.01);
    EXPECT_LE(std::stod(at(rows, i, "path_error_max_blu")), 0.7072);
    EXPECT_EQ(at(rows, i, "cells"), "not run (--no-synth)");
    EXPECT_EQ(at(rows, i, "rtl_cosim"), "not run (--no-rtl)");
  }
  const std::string svg = read_text_file(dir + "/s.svg");
  EXPECT_EQ(svg.rfind("<?xml", 0), 0u);
  EXPECT_NE(svg.find("</svg>"), std::string::npos);
  EXPECT_NE(read_text_file(dir + "/s.md").find("| 11 |"), std::string::npos);
  EXPECT_NE(r.output.find("| width | blocks |"), std::string::npos) << "the table on stdout";
}

TEST(SweepCli, BadOptionsAndInputsExitOneAndWriteNothing) {
  const std::string dir = test::fresh_dir();
  const std::string circle = test::example("contours/circle_r50.json");
  const std::string outputs = " --no-synth --no-rtl --csv " + dir + "/s.csv --svg " + dir + "/s.svg";
  test::CommandResult r = test::run_ncinterp("sweep " + circle + " --widths 11:10" + outputs);
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_NE(r.output.find("--widths: 11:10 runs backwards"), std::string::npos) << r.output;
  r = test::run_ncinterp("sweep " + circle + " --widths 8:40" + outputs);
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_NE(r.output.find("40 is outside 2..32 bits"), std::string::npos) << r.output;
  // G-code with G93 is a tape, not a contour: the first stage's reader names file and line.
  r = test::run_ncinterp("sweep " + test::example("gear.nc") + " --widths 10" + outputs);
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_NE(r.output.find("gear.nc:4: unsupported code G93"), std::string::npos) << r.output;
  EXPECT_TRUE(std::filesystem::is_empty(dir));
}

TEST(SweepCli, AToolNotOnPathIsStatedInItsColumns) {
  const std::string dir = test::fresh_dir();
  const test::CommandResult r = test::run_ncinterp(
      "sweep " + test::example("contours/circle_r50.json") + " --widths 12 --feed 20000 --reader-cps 100000" +
          " --no-rtl --cache " + dir + " --csv " + dir + "/s.csv",
      "PATH=/nonexistent ");
  ASSERT_EQ(r.exit_code, 0) << r.output;
  const auto rows = csv_rows(read_text_file(dir + "/s.csv"));
  ASSERT_EQ(rows.size(), 2u);
  for (const char* c : {"cells", "flip_flops", "ice40_luts", "ice40_logic_cells", "fmax_mhz"})
    EXPECT_EQ(at(rows, 1, c), "yosys not on PATH") << c;
  EXPECT_EQ(at(rows, 1, "check"), "pass");  // the rest of the row is measured
}

}  // namespace
}  // namespace ncinterp::sweep
