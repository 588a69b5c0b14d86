// `ncinterp sweep` from the command line: a small range end to end, bad options, a tool
// missing from PATH stated in its columns; a grid planned, run one point at a time (by
// hand in reverse order, by GNU parallel) and collected gives the in-process tables; a
// rerun measures nothing.
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
  EXPECT_EQ(at(rows, 1, "IncWidth"), "10");
  EXPECT_EQ(at(rows, 2, "IncWidth"), "11");
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
  EXPECT_NE(stdout_.find("| IncWidth | blocks |"), std::string::npos) << "the table on stdout";
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
  for (const char* c :
       {"cells", "flip_flops", "ice40_luts", "ice40_logic_cells", "fmax_mhz", "hx1k_logic_cells", "hx1k_fmax_mhz"})
    EXPECT_EQ(at(rows, 1, c), "yosys not on PATH") << c;
  EXPECT_EQ(at(rows, 1, "check"), "pass");  // the rest of the row is measured
}

TEST_F(SweepCli, RefusedPointsAreNamedOnceAndAllRefusedIsAFailedRun) {
  // A 2 um circle is refused at every width (it lies within the tolerance of its start).
  const std::string tiny = dir_.string() + ".tiny.nc";
  std::ofstream(tiny) << "G21 G90\nG0 X0.002 Y0\nG3 X0.002 Y0 I-0.002 J0 F100\nM2\n";
  const std::string cache = dir_.string() + ".cache";
  EXPECT_EQ(run("sweep " + tiny + " --widths 2:3 --no-synth --no-rtl --cache " + cache + " --csv " + path("s.csv")), 1);
  std::filesystem::remove(tiny);
  std::filesystem::remove_all(cache);
  for (const char* w : {"IncWidth=2", "IncWidth=3"}) {
    const size_t at = stderr_.find(std::string("sweep: ") + w);
    ASSERT_NE(at, std::string::npos) << stderr_;
    EXPECT_NE(stderr_.find(", " + tiny + ": refused: ", at), std::string::npos) << stderr_;
  }
  EXPECT_NE(stderr_.find("no point of the grid could tape any input"), std::string::npos) << stderr_;
  EXPECT_TRUE(files().empty());
}

TEST_F(SweepCli, UsageAndOutputErrorsExitOneAndWriteNothing) {
  EXPECT_EQ(run("sweep " + circle_ + " --jobs 0"), 1);  // not a positive number
  EXPECT_EQ(std::count(stderr_.begin(), stderr_.end(), '\n'), 1) << stderr_;
  const std::string cache = dir_.string() + ".cache";
  EXPECT_EQ(run("sweep " + circle_ + " --widths 10 --no-synth --no-rtl --cache " + cache + " --csv " +
                path("s.csv") + " --svg " + path("nodir/s.svg")), 1);
  std::filesystem::remove_all(cache);
  EXPECT_NE(stderr_.find("nodir/s.svg"), std::string::npos) << stderr_;
  EXPECT_TRUE(files().empty());
}

class SweepGrid : public SweepCli {
 protected:
  // 4 points: IncWidth 10, 11 x PosWidth 16, 32 (16 bits cannot hold the circle: FAIL).
  std::string grid(const std::string& cache) const {
    return "sweep " + circle_ + " --widths 10:11 --pos-widths 16,32 --no-synth --no-rtl" + fast_ + " --cache " + cache;
  }
  std::vector<std::string> jobs(const std::string& cache) const {
    std::vector<std::string> lines;
    std::istringstream in(slurp(cache + "/jobs.txt"));
    for (std::string line; std::getline(in, line);) lines.push_back(line);
    return lines;
  }
  void TearDown() override {
    for (const char* c : {".local", ".planned", ".parallel"}) std::filesystem::remove_all(dir_.string() + c);
    SweepCli::TearDown();
  }
};

TEST_F(SweepGrid, PlannedPointsRunInAnyOrderCollectToTheInProcessTables) {
  const std::string local = dir_.string() + ".local", planned = dir_.string() + ".planned";
  ASSERT_EQ(run(grid(local) + " --jobs 2 --csv " + path("local.csv") + " --pareto-md " + path("front.md") +
                " --pareto-svg " + path("front.svg") + " --times " + path("times.csv")),
            0)
      << stderr_;
  EXPECT_NE(stderr_.find("4 of 4 points measured"), std::string::npos) << stderr_;
  const auto rows = csv_rows(slurp(path("local.csv")));
  ASSERT_EQ(rows.size(), 5u);
  EXPECT_EQ(at(rows, 1, "PosWidth"), "16");
  EXPECT_EQ(at(rows, 1, "check").rfind("FAIL circle_r50.json", 0), 0u) << at(rows, 1, "check");
  EXPECT_EQ(at(rows, 2, "check"), "pass");
  EXPECT_NE(slurp(path("front.md")).find("no area measured"), std::string::npos);
  EXPECT_NE(slurp(path("front.svg")).find("</svg>"), std::string::npos);
  EXPECT_EQ(csv_rows(slurp(path("times.csv"))).size(), 5u);

  ASSERT_EQ(run(grid(planned) + " --plan --slurm"), 0) << stderr_;
  EXPECT_NE(slurp(planned + "/sweep.sbatch").find("#SBATCH --array=1-4\n"), std::string::npos);
  std::vector<std::string> lines = jobs(planned);
  ASSERT_EQ(lines.size(), 4u);
  EXPECT_NE(lines[0].find(" sweep --run-one "), std::string::npos) << lines[0];
  std::reverse(lines.begin(), lines.end());
  for (const std::string& l : lines) ASSERT_EQ(std::system((l + " 2>/dev/null").c_str()), 0) << l;
  ASSERT_EQ(run("sweep --collect " + planned + " --csv " + path("collected.csv")), 0) << stderr_;
  EXPECT_EQ(slurp(path("collected.csv")), slurp(path("local.csv")));

  // Everything measured: a rerun measures nothing and gives the same table.
  ASSERT_EQ(run(grid(local) + " --csv " + path("again.csv")), 0) << stderr_;
  EXPECT_NE(stderr_.find("0 of 4 points measured"), std::string::npos) << stderr_;
  EXPECT_EQ(slurp(path("again.csv")), slurp(path("local.csv")));
}

TEST_F(SweepGrid, GnuParallelRunsThePlan) {
  ASSERT_EQ(std::system("command -v parallel >/dev/null 2>&1"), 0) << "GNU parallel not installed (scripts/setup.sh installs it)";
  const std::string local = dir_.string() + ".local", par = dir_.string() + ".parallel";
  ASSERT_EQ(run(grid(local) + " --csv " + path("local.csv")), 0) << stderr_;
  ASSERT_EQ(run(grid(par) + " --plan"), 0) << stderr_;
  ASSERT_EQ(std::system(("parallel --will-cite -j 2 < " + par + "/jobs.txt 2>/dev/null").c_str()), 0);
  ASSERT_EQ(run("sweep --collect " + par + " --csv " + path("par.csv")), 0) << stderr_;
  EXPECT_EQ(slurp(path("par.csv")), slurp(path("local.csv")));
}

TEST_F(SweepGrid, RunOneAndCollectNeedAPlan) {
  EXPECT_EQ(run("sweep --collect " + path("nothing")), 1);
  EXPECT_NE(stderr_.find("nothing/plan.json: no plan"), std::string::npos) << stderr_;
  EXPECT_EQ(run("sweep " + circle_ + " --pos-widths 16 --slurm --no-synth --no-rtl --cache " + path("c")), 1);
  EXPECT_NE(stderr_.find("--slurm writes a job array with --plan"), std::string::npos) << stderr_;
}

}  // namespace
}  // namespace ncinterp::sweep
