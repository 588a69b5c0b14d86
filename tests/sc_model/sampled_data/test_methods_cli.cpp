// `ncinterp methods` as a user runs it: the CSV's columns, the SVG, and bad options or a
// failing run ending non-zero with one line on stderr and no output file.
#include <gtest/gtest.h>

#include <sys/wait.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>
#include <string>
#include <vector>

namespace {

namespace fs = std::filesystem;

struct CliRun {
  int code = -1;
  std::string out, err;
};

std::string slurp(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

std::vector<std::string> split(const std::string& line, char sep) {
  std::vector<std::string> cells;
  std::stringstream s(line);
  std::string cell;
  while (std::getline(s, cell, sep)) cells.push_back(cell);
  if (!line.empty() && line.back() == sep) cells.emplace_back();
  return cells;
}

class MethodsCli : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() /
           ("ncinterp_methods_cli_" + std::string(::testing::UnitTest::GetInstance()->current_test_info()->name()));
    fs::remove_all(dir_);
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }

  CliRun ncinterp(const std::string& args) {
    const fs::path out = dir_ / "stdout.txt", err = dir_ / "stderr.txt";
    const std::string cmd = std::string(NCINTERP_BINARY) + " methods " + args + " >" + out.string() + " 2>" +
                            err.string();
    const int status = std::system(cmd.c_str());
    CliRun r;
    r.code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
    r.out = slurp(out);
    r.err = slurp(err);
    fs::remove(out);
    fs::remove(err);
    return r;
  }

  // Files in the test directory (outputs and any temporary left behind).
  std::vector<std::string> files() const {
    std::vector<std::string> names;
    for (const auto& e : fs::directory_iterator(dir_)) names.push_back(e.path().filename().string());
    return names;
  }

  fs::path dir_;
};

// Small enough to run in well under a second.
const std::string kQuick = "--radius 1 --h 0.02 --turns 2";

TEST_F(MethodsCli, CsvHasTheMethodFirstAndNumbersElsewhere) {
  const fs::path csv = dir_ / "m.csv";
  const CliRun r = ncinterp(kQuick + " --csv " + csv.string());
  ASSERT_EQ(r.code, 0) << r.err;
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
  EXPECT_NE(r.out.find("hardware"), std::string::npos);
}

TEST_F(MethodsCli, WritesTheSvg) {
  const fs::path svg = dir_ / "m.svg";
  const CliRun r = ncinterp(kQuick + " --svg " + svg.string());
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_NE(slurp(svg).find("<svg"), std::string::npos);
}

TEST_F(MethodsCli, BadOptionsFailWithoutWritingAFile) {
  const fs::path csv = dir_ / "m.csv";
  for (const std::string bad : {"--h 0", "--h 0.9", "--radius -1", "--radius 0", "--turns 1", "--word-bits 4",
                                "--word-bits 63", "--start k2", "--h abc", "--bogus 1"}) {
    const CliRun r = ncinterp(bad + " --csv " + csv.string());
    EXPECT_NE(r.code, 0) << bad;
    EXPECT_FALSE(r.err.empty()) << bad;
    EXPECT_TRUE(files().empty()) << bad;
  }
}

TEST_F(MethodsCli, UnwritableOutputFailsAndWritesNothing) {
  const fs::path csv = dir_ / "m.csv";
  const CliRun r = ncinterp(kQuick + " --csv " + csv.string() + " --svg " + (dir_ / "missing" / "m.svg").string());
  EXPECT_EQ(r.code, 1);
  EXPECT_NE(r.err.find("m.svg"), std::string::npos) << r.err;
  EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
  EXPECT_TRUE(files().empty());
}

// K1 at h = 0.5 multiplies its radius by about 4.5 every turn: a thousand turns leave the
// double range. The run fails before any output is written.
TEST_F(MethodsCli, FailingRunWritesNothing) {
  const fs::path csv = dir_ / "m.csv";
  const CliRun r = ncinterp("--radius 1 --h 0.5 --turns 1000 --csv " + csv.string());
  EXPECT_EQ(r.code, 1);
  EXPECT_NE(r.err.find("K1"), std::string::npos) << r.err;
  EXPECT_TRUE(files().empty());
}

}  // namespace
