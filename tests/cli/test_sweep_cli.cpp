// `ncinterp sweep` from the command line: a small range end to end, bad options, a tool
// missing from PATH stated in its columns.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "cli_test.h"

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

class SweepCli : public ncinterp::test::CliTest {
 protected:
  // Inputs run fast: about a second of machine time for the circle, a quick reader.
  const std::string circle_ = test::example("contours/circle_r50.json");
  const std::string fast_ = " --feed 20000 --reader-cps 100000";
};

TEST_F(SweepCli, SmallRangeWritesOneRowPerWidthAndThePlot) {
  // The cache goes beside the scratch directory, so the directory holds the outputs only.
  const std::string cache = dir_.string() + ".cache";
  ASSERT_EQ(run("sweep " + circle_ + " --widths 10:11 --jobs 2 --no-synth --no-rtl" + fast_ + " --cache " + cache +
                " --csv " + path("s.csv") + " --svg " + path("s.svg") + " --markdown " + path("s.md")),
            0)
      << stderr_;
  std::filesystem::remove_all(cache);
  EXPECT_EQ(files(), (std::vector<std::string>{"s.csv", "s.md", "s.svg"}));
  const auto rows = csv_rows(slurp(path("s.csv")));
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
  const std::string svg = slurp(path("s.svg"));
  EXPECT_EQ(svg.rfind("<?xml", 0), 0u);
  EXPECT_NE(svg.find("</svg>"), std::string::npos);
  EXPECT_NE(slurp(path("s.md")).find("| 11 |"), std::string::npos);
  EXPECT_NE(stdout_.find("| width | blocks |"), std::string::npos) << "the table on stdout";
}

TEST_F(SweepCli, BadOptionsAndInputsExitOneAndWriteNothing) {
  const std::string outputs = " --no-synth --no-rtl --csv " + path("s.csv") + " --svg " + path("s.svg");
  EXPECT_EQ(run("sweep " + circle_ + " --widths 11:10" + outputs), 1);
  EXPECT_NE(stderr_.find("--widths: 11:10 runs backwards"), std::string::npos) << stderr_;
  EXPECT_EQ(run("sweep " + circle_ + " --widths 8:40" + outputs), 1);
  EXPECT_NE(stderr_.find("40 is outside 2..32 bits"), std::string::npos) << stderr_;
  // G-code with G93 is a tape, not a contour: the first stage's reader names file and line.
  EXPECT_EQ(run("sweep " + test::example("gear.nc") + " --widths 10" + outputs), 1);
  EXPECT_NE(stderr_.find("gear.nc:4: unsupported code G93"), std::string::npos) << stderr_;
  EXPECT_TRUE(files().empty());
}

TEST_F(SweepCli, AToolNotOnPathIsStatedInItsColumns) {
  const std::string cache = dir_.string() + ".cache";
  const char* old_path = std::getenv("PATH");
  const std::string saved = old_path ? old_path : "";
  ::setenv("PATH", "/nonexistent", 1);  // the shell and ncinterp are run by absolute path
  const int code =
      run("sweep " + circle_ + " --widths 12 --no-rtl" + fast_ + " --cache " + cache + " --csv " + path("s.csv"));
  ::setenv("PATH", saved.c_str(), 1);
  std::filesystem::remove_all(cache);
  ASSERT_EQ(code, 0) << stderr_;
  const auto rows = csv_rows(slurp(path("s.csv")));
  ASSERT_EQ(rows.size(), 2u);
  for (const char* c : {"cells", "flip_flops", "ice40_luts", "ice40_logic_cells", "fmax_mhz"})
    EXPECT_EQ(at(rows, 1, c), "yosys not on PATH") << c;
  EXPECT_EQ(at(rows, 1, "check"), "pass");  // the rest of the row is measured
}

TEST_F(SweepCli, RefusedPointsAreNamedOnceAndAllRefusedIsAFailedRun) {
  // A 2 um circle is refused at every width (it lies within the tolerance of its start).
  const std::string tiny = dir_.string() + ".tiny.nc";
  std::ofstream(tiny) << "G21 G90\nG0 X0.002 Y0\nG3 X0.002 Y0 I-0.002 J0 F100\nM2\n";
  EXPECT_EQ(run("sweep " + tiny + " --widths 2:3 --no-synth --no-rtl --csv " + path("s.csv")), 1);
  std::filesystem::remove(tiny);
  EXPECT_NE(stderr_.find("sweep: W=2, " + tiny + ": refused: "), std::string::npos) << stderr_;
  EXPECT_NE(stderr_.find("sweep: W=3, " + tiny + ": refused: "), std::string::npos) << stderr_;
  EXPECT_NE(stderr_.find("no width of --widths 2:3 could tape any input"), std::string::npos) << stderr_;
  EXPECT_TRUE(files().empty());
}

TEST_F(SweepCli, UsageAndOutputErrorsExitOneAndWriteNothing) {
  EXPECT_EQ(run("sweep " + circle_), 1);  // --widths is required
  EXPECT_EQ(std::count(stderr_.begin(), stderr_.end(), '\n'), 1) << stderr_;
  EXPECT_EQ(run("sweep " + circle_ + " --widths 10 --no-synth --no-rtl --csv " + path("s.csv") +
                " --svg " + path("nodir/s.svg")), 1);
  EXPECT_NE(stderr_.find("nodir/s.svg"), std::string::npos) << stderr_;
  EXPECT_TRUE(files().empty());
}

}  // namespace
}  // namespace ncinterp::sweep
