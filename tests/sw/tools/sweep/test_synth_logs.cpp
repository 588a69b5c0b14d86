// The yosys and nextpnr-ice40 log parsers on captured logs (logs/README.md says where each
// comes from): the numbers the sweep reports, and nothing when the line is not there.
#include <gtest/gtest.h>

#include "sweep_test_support.h"
#include "synth_logs.h"

namespace ncinterp::sweep {
namespace {

TEST(SynthLogs, GenericStatIsTheDesignHierarchyTotal) {
  const std::optional<YosysStat> s = parse_yosys_stat(test::log_snippet("yosys_synth.log"));
  ASSERT_TRUE(s);
  // Not the per-module sections before it (132, 219 cells): the whole design.
  EXPECT_EQ(s->cells, 6026u);
  EXPECT_EQ(s->flip_flops(), 776u);  // $_DFF_P_ 9 + $_SDFFE_* 711 + $_SDFF_* 56
  EXPECT_EQ(s->count("$_XOR_"), 469u);
  EXPECT_EQ(s->count("$_DLATCH_P_"), 0u);
}

TEST(SynthLogs, Ice40StatCountsLutsAndIce40FlipFlops) {
  const std::optional<YosysStat> s = parse_yosys_stat(test::log_snippet("yosys_synth_ice40.log"));
  ASSERT_TRUE(s);
  EXPECT_EQ(s->cells, 2752u);
  EXPECT_EQ(s->count("SB_LUT4"), 1575u);
  EXPECT_EQ(s->count("SB_CARRY"), 471u);
  EXPECT_EQ(s->flip_flops(), 706u);  // SB_DFF 9 + SB_DFFESR 641 + SB_DFFSR 55 + SB_DFFSS 1
}

TEST(SynthLogs, NoStatisticsIsNoValueAndTheErrorLineIsTheReason) {
  const std::string log = test::log_snippet("yosys_syntax_error.log");
  EXPECT_FALSE(parse_yosys_stat(log));
  EXPECT_EQ(first_error_line(log), "bad.sv:2: ERROR: syntax error, unexpected ';'");
  EXPECT_EQ(first_error_line("all fine\n"), "");
}

TEST(SynthLogs, NextpnrFmaxIsTheLastReportAfterRouting) {
  const NextpnrReport r = parse_nextpnr_log(test::log_snippet("nextpnr_hx8k.log"));
  ASSERT_TRUE(r.fmax_mhz);
  EXPECT_DOUBLE_EQ(*r.fmax_mhz, 45.76);  // not the placement estimate, 46.43
  ASSERT_TRUE(r.logic_cells && r.logic_cells_available);
  EXPECT_EQ(*r.logic_cells, 2073u);
  EXPECT_EQ(*r.logic_cells_available, 7680u);
}

TEST(SynthLogs, NextpnrOnATooSmallPartHasNoFmaxAndSaysWhy) {
  const std::string log = test::log_snippet("nextpnr_too_big.log");
  const NextpnrReport r = parse_nextpnr_log(log);
  EXPECT_FALSE(r.fmax_mhz);
  ASSERT_TRUE(r.logic_cells && r.logic_cells_available);
  EXPECT_GT(*r.logic_cells, *r.logic_cells_available);
  EXPECT_NE(first_error_line(log).find("no BELs remaining"), std::string::npos) << first_error_line(log);
}

TEST(SynthLogs, ErrorLinesOfVerilatorAndCompilersAreFound) {
  EXPECT_EQ(first_error_line("%Warning-X: w\n%Error-PINNOTFOUND: a.sv:1: Pin not found\nninja: error: x\n"),
            "%Error-PINNOTFOUND: a.sv:1: Pin not found");
  EXPECT_EQ(first_error_line("  main.cpp:3:1: error: expected ';'  \n"), "main.cpp:3:1: error: expected ';'");
}

}  // namespace
}  // namespace ncinterp::sweep
