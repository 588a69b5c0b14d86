// `ncinterp cosim` as a user runs it: exit codes, the one-line messages, the report and the
// VCD window around a mismatch, and no stray files.
// Idea: a mismatch is made by injecting a fault into the golden model, so the test knows the
// exact cycle, block and signal the scoreboard must name.
#include <gtest/gtest.h>

#include <algorithm>
#include <string>

#include "cli_test.h"

namespace ncinterp::test {
namespace {

const std::string kFast = " --clock-hz 1e5 --reader-cps 1e5";

class CosimCli : public CliTest {
 protected:
  int cosim(const std::string& args) { return run("cosim " + args); }
  const std::string gear_ = example("gear.nc");
};

TEST_F(CosimCli, GoodTapeAgreesToTheEnd) {
  ASSERT_EQ(cosim(gear_ + kFast + " --report " + path("ok.json")), 0) << stderr_ << stdout_;
  EXPECT_NE((stdout_ + stderr_).find("agree on all"), std::string::npos) << stdout_;
  const std::string report = slurp(path("ok.json"));
  EXPECT_NE(report.find("\"status\": \"match\""), std::string::npos) << report;
  EXPECT_NE(report.find("\"end\": \"done\""), std::string::npos) << report;
}

TEST_F(CosimCli, InjectedFaultNamesCycleBlockAndSignal) {
  const int code = cosim(gear_ + kFast + " --inject-fault stuck-step:20000:y --vcd " +
                         path("m.vcd") + " --vcd-window 100 --report " + path("m.json"));
  ASSERT_EQ(code, 2) << stderr_ << stdout_;
  const std::string out = stdout_ + stderr_;
  EXPECT_NE(out.find("differ at cycle 20000, block N"), std::string::npos) << out;
  EXPECT_NE(out.find("signal step_y_o: expected 1, actual 0 (19999 cycles matched)"),
            std::string::npos)
      << out;
  const std::string vcd = slurp(path("m.vcd"));
  EXPECT_NE(vcd.find(" step_y_o "), std::string::npos) << "VCD lacks step_y_o";
  EXPECT_NE(slurp(path("m.json")).find("\"signal\": \"step_y_o\""), std::string::npos);
}

TEST_F(CosimCli, BadTapeStopsBothEnginesWithTheSameError) {
  write("bad.nc", "%\nN1 G01 X0.001 F100.000\nN2 G01 Q1\n");
  ASSERT_EQ(cosim(path("bad.nc") + kFast), 1) << stdout_ << stderr_;
  EXPECT_NE((stdout_ + stderr_).find("bad.nc: block N2, offset 32: unknown address letter"),
            std::string::npos)
      << stdout_ << stderr_;
}

TEST_F(CosimCli, CycleLimitAndMissingTapeExitCleanly) {
  ASSERT_EQ(cosim(gear_ + " --max-cycles 500"), 3) << stdout_ << stderr_;
  EXPECT_NE((stdout_ + stderr_).find("cycle limit (500 cycles)"), std::string::npos);
  EXPECT_EQ(cosim(path("missing.nc") + " --report " + path("missing.json")), 1);
  EXPECT_EQ(files(), std::vector<std::string>{}) << "a report or temporary file was left";
}

TEST_F(CosimCli, UsageAndOutputErrorsExitOneAndWriteNothing) {
  EXPECT_EQ(cosim(gear_ + " --max-cycles many"), 1);
  EXPECT_EQ(std::count(stderr_.begin(), stderr_.end(), '\n'), 1) << stderr_;
  EXPECT_EQ(cosim(gear_ + kFast + " --report " + path("nodir/r.json")), 1);
  EXPECT_NE(stderr_.find("nodir/r.json"), std::string::npos) << stderr_;
  EXPECT_EQ(cosim(""), 1);
  EXPECT_TRUE(files().empty());
}

}  // namespace
}  // namespace ncinterp::test
