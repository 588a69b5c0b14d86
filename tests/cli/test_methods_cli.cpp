// `ncinterp methods` as a user runs it: the CSV's columns, the SVG, and bad options or a
// failing run ending non-zero with one line on stderr and no output file.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "cli_test.h"

namespace {

namespace fs = std::filesystem;

std::vector<std::string> split(const std::string& line, char sep) {
  std::vector<std::string> cells;
  std::stringstream s(line);
  std::string cell;
  while (std::getline(s, cell, sep)) cells.push_back(cell);
  if (!line.empty() && line.back() == sep) cells.emplace_back();
  return cells;
}

class MethodsCli : public ncinterp::test::CliTest {
 protected:
  int methods(const std::string& args) { return run("methods " + args); }
};

// Small enough to run in well under a second.
const std::string kQuick = "--radius 1 --h 0.02 --turns 2";

TEST_F(MethodsCli, CsvHasTheMethodFirstAndNumbersElsewhere) {
  const fs::path csv = dir_ / "m.csv";
  const int code = methods(kQuick + " --csv " + csv.string());
  ASSERT_EQ(code, 0) << stderr_;
  std::istringstream in(slurp(csv));
  std::string line;
  ASSERT_TRUE(std::getline(in, line));
  const std::vector<std::string> header = split(line, ',');
  ASSERT_GE(header.size(), 10u);
  EXPECT_EQ(header[0], "method");
  for (const char* column : {"radius_mm", "h", "error_mm", "path_error_mm", "drift_per_turn_mm", "local_error_rel",
                             "paper_error_mm", "fixed_error_mm"})
    EXPECT_NE(std::find(header.begin(), header.end(), column), header.end()) << column;
  std::multiset<std::string> methods;
  while (std::getline(in, line)) {
    const std::vector<std::string> cells = split(line, ',');
    ASSERT_EQ(cells.size(), header.size()) << line;
    methods.insert(cells[0]);
    for (size_t i = 1; i < cells.size(); ++i) {
      if (cells[i].empty()) continue;  // not applicable to this method
      char* end = nullptr;
      std::strtod(cells[i].c_str(), &end);
      EXPECT_EQ(*end, '\0') << header[i] << " = '" << cells[i] << "' in " << line;
    }
  }
  EXPECT_EQ(methods, (std::multiset<std::string>{"L1", "K1", "K2", "K3", "K4", "K5", "K6", "K7"}));
  EXPECT_NE(stdout_.find("hardware"), std::string::npos);
}

TEST_F(MethodsCli, WritesTheSvg) {
  const fs::path svg = dir_ / "m.svg";
  const int code = methods(kQuick + " --svg " + svg.string());
  ASSERT_EQ(code, 0) << stderr_;
  EXPECT_NE(slurp(svg).find("<svg"), std::string::npos);
}

TEST_F(MethodsCli, BadOptionsFailWithoutWritingAFile) {
  const fs::path csv = dir_ / "m.csv";
  for (const std::string bad : {"--h 0", "--h 0.9", "--radius -1", "--radius 0", "--turns 1", "--word-bits 4",
                                "--word-bits 63", "--start k2", "--h abc", "--bogus 1"}) {
    const int code = methods(bad + " --csv " + csv.string());
    EXPECT_NE(code, 0) << bad;
    EXPECT_FALSE(stderr_.empty()) << bad;
    EXPECT_TRUE(files().empty()) << bad;
  }
}

TEST_F(MethodsCli, UnwritableOutputFailsAndWritesNothing) {
  const fs::path csv = dir_ / "m.csv";
  const int code = methods(kQuick + " --csv " + csv.string() + " --svg " + (dir_ / "missing" / "m.svg").string());
  EXPECT_EQ(code, 1);
  EXPECT_NE(stderr_.find("m.svg"), std::string::npos) << stderr_;
  EXPECT_EQ(std::count(stderr_.begin(), stderr_.end(), '\n'), 1) << stderr_;
  EXPECT_TRUE(files().empty());
}

// K1 at h = 0.5 multiplies its radius by about 4.5 every turn: a thousand turns leave the
// double range. The run fails before any output is written.
TEST_F(MethodsCli, FailingRunWritesNothing) {
  const fs::path csv = dir_ / "m.csv";
  const int code = methods("--radius 1 --h 0.5 --turns 1000 --csv " + csv.string());
  EXPECT_EQ(code, 1);
  EXPECT_NE(stderr_.find("K1"), std::string::npos) << stderr_;
  EXPECT_TRUE(files().empty());
}

TEST_F(MethodsCli, UsageErrorsExitOneWithOneLine) {
  EXPECT_EQ(run("methods --turns 5000"), 1);  // outside 2..1000
  EXPECT_EQ(std::count(stderr_.begin(), stderr_.end(), '\n'), 1) << stderr_;
  EXPECT_EQ(run("methods --no-such-option"), 1);
  EXPECT_TRUE(files().empty());
}

}  // namespace
