// `ncinterp check` as a user runs it: exit codes, the report file, one-line errors naming
// file, block and offset, and no output file left behind when the input is bad.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <nlohmann/json.hpp>

#include "cli_test.h"
#include "regression_support.h"
#include "tape/tape.h"

namespace ncinterp::regression {
namespace {

class CheckCli : public test::CliTest {
 protected:
  // The circle example's tape, written like `ncinterp tape` does (feed high for speed).
  std::string circle_tape(double tol_mm = 0.01) {
    Case c;
    c.contour = firststage::read_contour(example_path("circle_r50.json"), {});
    c.first_stage.tol_mm = tol_mm;
    c.first_stage.feed_mm_min = 20000;
    const auto r = firststage::run_first_stage(c.contour, c.first_stage);
    tape::write_tape_file(path("circle.tape"), firststage::make_program(r, c.first_stage),
                          firststage::tape_format(c.first_stage));
    return path("circle.tape");
  }
};

TEST_F(CheckCli, PassingTapeExitsZeroAndWritesTheReport) {
  const std::string tape = circle_tape();
  const std::string report = path("r.json");
  const int code = run("check " + tape + " --contour " + example_path("circle_r50.json") +
                         " --reader-cps 100000 --report " + report);
  ASSERT_EQ(code, 0) << stdout_ << stderr_;
  EXPECT_NE(stdout_.find("PASS"), std::string::npos) << stdout_;
  const auto j = nlohmann::json::parse(slurp(report));
  EXPECT_EQ(j["status"], "pass");
  EXPECT_LE(j["total_error"]["max_mm"].get<double>(), 0.01);
  EXPECT_GT(j["total_error"]["max_mm"].get<double>(), 0.005);
  EXPECT_EQ(j["violation_count"], 0);
  EXPECT_EQ(j["per_block"].size(), j["blocks"].get<size_t>());
  EXPECT_TRUE(j["total_error"]["at"].contains("block"));
}

// A limit switch mid-part: every rule holds up to it, exit 5, status "stopped", and the
// report names the stop, the block and where the machine stands.
TEST_F(CheckCli, LimitSwitchStopsTheRunWithExitFiveAndTheStopInTheReport) {
  const std::string tape = circle_tape();
  const std::string report = path("r.json");
  const int code = run("check " + tape + " --contour " + example_path("circle_r50.json") +
                       " --reader-cps 100000 --accel 500 --events limit-x@0.5s --report " + report);
  ASSERT_EQ(code, 5) << stdout_ << stderr_;
  EXPECT_NE(stdout_.find("X limit switch at 0.5"), std::string::npos) << stdout_;
  EXPECT_NE(stdout_.find("STOPPED"), std::string::npos) << stdout_;
  const auto j = nlohmann::json::parse(slurp(report));
  EXPECT_EQ(j["status"], "stopped");
  EXPECT_EQ(j["violation_count"], 0);
  EXPECT_EQ(j["stop"]["code"], 15);
  EXPECT_EQ(j["stop"]["message"], "X limit switch");
  EXPECT_GT(j["stop"]["block"].get<int>(), 0);
  EXPECT_EQ(j["stop"]["position"], j["final_position"]);
  EXPECT_FALSE(j["done"].get<bool>());
}

TEST_F(CheckCli, SvgShowsThePartTheWorstPointAndTheErrorAlongThePath) {
  const std::string tape = circle_tape();
  const std::string report = path("r.json"), svg = path("p.svg");
  const int code = run("check " + tape + " --contour " + example_path("circle_r50.json") +
                         " --reader-cps 100000 --report " + report + " --svg " + svg);
  ASSERT_EQ(code, 0) << stdout_ << stderr_;
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
  const std::string report = path("r.json");
  const int code = run("check " + tape + " --contour " + example_path("circle_r50.json") +
                         " --tol 0.01 --reader-cps 100000 --report " + report);
  EXPECT_EQ(code, 2) << stdout_ << stderr_;
  EXPECT_NE(stdout_.find("FAIL"), std::string::npos);
  EXPECT_NE(stdout_.find("tolerance in block N"), std::string::npos) << stdout_;
  const auto j = nlohmann::json::parse(slurp(report));
  EXPECT_EQ(j["status"], "fail");
  EXPECT_EQ(j["violations"][0]["rule"], "tolerance");
}

TEST_F(CheckCli, BadTapeIsOneLineNamingBlockAndOffsetWithNoReport) {
  write("bad.nc", "%\nG17 G21 G91 G93\nN1 G01 X1.000 Y2.000 F100.000\nN2 G01 X1.0Q0 F100.000\nM02\n%\n");
  const std::string report = path("r.json");
  const int code = run("check " + path("bad.nc") + " --report " + report);
  EXPECT_EQ(code, 1);
  EXPECT_NE(stderr_.find("bad.nc: block N2, offset"), std::string::npos) << stderr_;
  EXPECT_EQ(std::count(stderr_.begin(), stderr_.end(), '\n'), 1) << stderr_;
  EXPECT_FALSE(std::filesystem::exists(report));
}

TEST_F(CheckCli, BadContourIsOneLineNamingFileAndLine) {
  const std::string tape = circle_tape();
  write("bad.json", "{\"start\": [0, 0],\n \"segments\": [\n {\"type\": \"spiral\"}]}\n");
  const std::string report = path("r.json");
  const int code = run("check " + tape + " --contour " + path("bad.json") +
                         " --report " + report);
  EXPECT_EQ(code, 1);
  EXPECT_NE(stderr_.find("bad.json:3"), std::string::npos) << stderr_;
  EXPECT_EQ(std::count(stderr_.begin(), stderr_.end(), '\n'), 1) << stderr_;
  EXPECT_FALSE(std::filesystem::exists(report));
}

TEST_F(CheckCli, CutterRadiusWithoutTheTapeStartIsRefused) {
  // Measured from the contour's start, a cutter-centre tape would fail everywhere.
  const std::string tape = circle_tape();
  const std::string report = path("r.json");
  const int code = run("check " + tape + " --contour " + example_path("circle_r50.json") +
                       " --cutter-radius 2 --report " + report);
  EXPECT_EQ(code, 1);
  EXPECT_NE(stderr_.find("--start"), std::string::npos) << stderr_;
  EXPECT_FALSE(std::filesystem::exists(report));
}

TEST_F(CheckCli, MissingTapeFileIsAnError) {
  const int code = run("check " + path("nope.tape"));
  EXPECT_EQ(code, 1);
  EXPECT_NE(stderr_.find("nope.tape"), std::string::npos) << stderr_;
}

TEST_F(CheckCli, BadSvgPathFailsBeforeTheRunAndLeavesNoReport) {
  const std::string tape = circle_tape();
  const int code = run("check " + tape + " --contour " + example_path("circle_r50.json") +
                       " --report " + path("r.json") + " --svg " + path("nodir/x.svg"));
  EXPECT_EQ(code, 1);
  EXPECT_NE(stderr_.find("nodir/x.svg"), std::string::npos) << stderr_;
  EXPECT_EQ(run("check " + tape + " --report " + tape), 1);  // the report would replace the tape
  EXPECT_NE(stderr_.find("is the input"), std::string::npos) << stderr_;
  EXPECT_EQ(files(), std::vector<std::string>{"circle.tape"});
}

// The bundled arc tape in both archs: the same path, the serial one (the default, as the
// boards play it) in a longer run (each arc is prepared in 2PN clocks instead of N, and the
// first one has no block ahead to hide it). The report names the arch.
TEST_F(CheckCli, BothArchsPlayTheSamePathTheSerialOneInMoreClocks) {
  const std::string tape = std::string(NCINTERP_EXAMPLES_DIR) + "/circle_r50.nc";
  ASSERT_EQ(run("check " + tape + " --arch parallel --report " + path("parallel.json")), 0) << stderr_;
  ASSERT_EQ(run("check " + tape + " --report " + path("serial.json")), 0) << stderr_;
  const auto parallel = nlohmann::json::parse(slurp(path("parallel.json")));
  const auto serial = nlohmann::json::parse(slurp(path("serial.json")));
  EXPECT_EQ(parallel["arch"], "parallel");
  EXPECT_EQ(serial["arch"], "serial");
  EXPECT_EQ(serial["final_position"], parallel["final_position"]);
  EXPECT_EQ(serial["pulse_clocks"], parallel["pulse_clocks"]);
  EXPECT_GT(serial["cycles"].get<uint64_t>(), parallel["cycles"].get<uint64_t>());
  EXPECT_EQ(run("check " + tape + " --arch bitserial"), 1);
  EXPECT_NE(stderr_.find("--arch"), std::string::npos) << stderr_;
}

TEST_F(CheckCli, UsageErrorsExitOne) {
  const std::string tape = circle_tape();
  EXPECT_EQ(run("check " + tape + " --engine fpga"), 1);
  EXPECT_EQ(std::count(stderr_.begin(), stderr_.end(), '\n'), 1) << stderr_;
  EXPECT_EQ(run("check " + tape + " --width 40"), 1);
  EXPECT_EQ(run("check"), 1);
}

}  // namespace
}  // namespace ncinterp::regression
