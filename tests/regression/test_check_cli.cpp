// `ncinterp check` as a user runs it: exit codes, the report file, one-line errors naming
// file, block and offset, and no output file left behind when the input is bad.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>

#include "regression_support.h"
#include "tape/tape.h"

namespace ncinterp::regression {
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

class CheckCli : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() /
           ("ncinterp_check_cli_" + std::to_string(::testing::UnitTest::GetInstance()->random_seed()) +
            "_" + ::testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::remove_all(dir_);
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }

  CliRun ncinterp(const std::string& args) {
    const fs::path out = dir_ / "stdout.txt", err = dir_ / "stderr.txt";
    const std::string cmd = std::string(NCINTERP_BINARY) + " " + args + " >" + out.string() + " 2>" + err.string();
    const int status = std::system(cmd.c_str());
    CliRun r;
    r.code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
    r.out = slurp(out);
    r.err = slurp(err);
    fs::remove(out);
    fs::remove(err);
    return r;
  }

  // The circle example's tape, written like `ncinterp tape` does (feed high for speed).
  std::string circle_tape(double tol_mm = 0.01) {
    Case c;
    c.contour = firststage::read_contour(example_path("circle_r50.json"), {});
    c.first_stage.tol_mm = tol_mm;
    c.first_stage.feed_mm_min = 20000;
    const auto r = firststage::run_first_stage(c.contour, c.first_stage);
    const std::string path = (dir_ / "circle.tape").string();
    tape::write_tape_file(path, firststage::make_program(r, c.first_stage), firststage::tape_format(c.first_stage));
    return path;
  }

  fs::path dir_;
};

TEST_F(CheckCli, PassingTapeExitsZeroAndWritesTheReport) {
  const std::string tape = circle_tape();
  const fs::path report = dir_ / "r.json";
  const CliRun r = ncinterp("check " + tape + " --contour " + example_path("circle_r50.json") +
                         " --reader-cps 100000 --report " + report.string());
  ASSERT_EQ(r.code, 0) << r.out << r.err;
  EXPECT_NE(r.out.find("PASS"), std::string::npos) << r.out;
  const auto j = nlohmann::json::parse(slurp(report));
  EXPECT_EQ(j["status"], "pass");
  EXPECT_LE(j["total_error"]["max_mm"].get<double>(), 0.01);
  EXPECT_GT(j["total_error"]["max_mm"].get<double>(), 0.005);
  EXPECT_EQ(j["violation_count"], 0);
  EXPECT_EQ(j["per_block"].size(), j["blocks"].get<size_t>());
  EXPECT_TRUE(j["total_error"]["at"].contains("block"));
}

TEST_F(CheckCli, SvgShowsThePartTheWorstPointAndTheErrorAlongThePath) {
  const std::string tape = circle_tape();
  const fs::path report = dir_ / "r.json", svg = dir_ / "p.svg";
  const CliRun r = ncinterp("check " + tape + " --contour " + example_path("circle_r50.json") +
                         " --reader-cps 100000 --report " + report.string() + " --svg " + svg.string());
  ASSERT_EQ(r.code, 0) << r.out << r.err;
  const std::string doc = slurp(svg);
  EXPECT_EQ(doc.rfind("<?xml", 0), 0u);
  EXPECT_NE(doc.find("</svg>"), std::string::npos);
  // PLplot writes text character by character as entities: decode to find the labels.
  std::string text;
  for (size_t at = doc.find("&#x"); at != std::string::npos; at = doc.find("&#x", at + 1))
    text += static_cast<char>(std::stoul(doc.substr(at + 3, doc.find(';', at) - at - 3), nullptr, 16));
  const auto j = nlohmann::json::parse(slurp(report));
  const std::string worst_block = "N" + std::to_string(j["total_error"]["at"]["block"].get<int>());
  for (const std::string& label : {std::string("worst point: ") + worst_block, std::string("tolerance (0 to 10.0 "),
                                   std::string("pulse path"), std::string("contour"), std::string("x (mm)"),
                                   std::string("path length (mm)")})
    EXPECT_NE(text.find(label), std::string::npos) << label;
}

TEST_F(CheckCli, TotalErrorOverTolExitsTwoAndNamesTheBlock) {
  const std::string tape = circle_tape(0.05);  // chords 5x coarser than the check's tol
  const fs::path report = dir_ / "r.json";
  const CliRun r = ncinterp("check " + tape + " --contour " + example_path("circle_r50.json") +
                         " --tol 0.01 --reader-cps 100000 --report " + report.string());
  EXPECT_EQ(r.code, 2) << r.out << r.err;
  EXPECT_NE(r.out.find("FAIL"), std::string::npos);
  EXPECT_NE(r.out.find("tolerance in block N"), std::string::npos) << r.out;
  const auto j = nlohmann::json::parse(slurp(report));
  EXPECT_EQ(j["status"], "fail");
  EXPECT_EQ(j["violations"][0]["rule"], "tolerance");
}

TEST_F(CheckCli, BadTapeIsOneLineNamingBlockAndOffsetWithNoReport) {
  std::ofstream(dir_ / "bad.nc") << "%\nG17 G21 G91 G93\nN1 G01 X1.000 Y2.000 F100.000\nN2 G01 X1.0Q0 F100.000\nM02\n%\n";
  const fs::path report = dir_ / "r.json";
  const CliRun r = ncinterp("check " + (dir_ / "bad.nc").string() + " --report " + report.string());
  EXPECT_EQ(r.code, 1);
  EXPECT_NE(r.err.find("bad.nc: block N2, offset"), std::string::npos) << r.err;
  EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
  EXPECT_FALSE(fs::exists(report));
}

TEST_F(CheckCli, BadContourIsOneLineNamingFileAndLine) {
  const std::string tape = circle_tape();
  std::ofstream(dir_ / "bad.json") << "{\"start\": [0, 0],\n \"segments\": [\n {\"type\": \"spiral\"}]}\n";
  const fs::path report = dir_ / "r.json";
  const CliRun r = ncinterp("check " + tape + " --contour " + (dir_ / "bad.json").string() +
                         " --report " + report.string());
  EXPECT_EQ(r.code, 1);
  EXPECT_NE(r.err.find("bad.json:3"), std::string::npos) << r.err;
  EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
  EXPECT_FALSE(fs::exists(report));
}

TEST_F(CheckCli, MissingTapeFileIsAnError) {
  const CliRun r = ncinterp("check " + (dir_ / "nope.tape").string());
  EXPECT_EQ(r.code, 1);
  EXPECT_NE(r.err.find("nope.tape"), std::string::npos) << r.err;
}

}  // namespace
}  // namespace ncinterp::regression
