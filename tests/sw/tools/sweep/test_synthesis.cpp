// The synthesis flow (yosys generic, synth_ice40, nextpnr-ice40 on the HX8K) on a tiny
// stand-in design, so the real tools run in seconds; failures and missing tools keep their
// reason in every column they leave empty; the cache returns what was measured, and a
// parameter set is synthesised once even when two points ask for it at once.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <thread>

#include "scratch_dir_test.h"
#include "sweep_test_support.h"
#include "synth_cache.h"
#include "synthesis.h"

namespace ncinterp::sweep {
namespace {

SynthesisSetup tiny_setup(const std::string& dir) {
  SynthesisSetup s;
  s.rtl_sources = {test::fixture("tiny_interp_top.sv")};
  s.fpga_top = test::fixture("tiny_fpga_top.sv");
  s.work_dir = dir + "/work";
  s.cache_dir = dir + "/cache";
  return s;
}

using Synthesis = ncinterp::test::ScratchDirTest;
using SynthCacheFiles = ncinterp::test::ScratchDirTest;

void expect_reason(const Measured& m, const std::string& start, const char* column) {
  EXPECT_FALSE(m.ok()) << column << " = " << *m.value;
  EXPECT_EQ(m.reason.rfind(start, 0), 0u) << column << ": " << m.reason;
}

TEST_F(Synthesis, MeasuresTheStandInDesignAndCachesTheResult) {
  const SynthesisSetup s = tiny_setup(dir_.string());
  const std::string key = synthesis_key(s);
  const SynthResult narrow = synthesize(4, s, key);
  const SynthResult wide = synthesize(12, s, key);
  for (const SynthResult* r : {&narrow, &wide}) {
    ASSERT_TRUE(r->cells.ok()) << r->cells.reason;
    ASSERT_TRUE(r->ice40_luts.ok()) << r->ice40_luts.reason;
    ASSERT_TRUE(r->ice40_logic_cells.ok()) << r->ice40_logic_cells.reason;
    ASSERT_TRUE(r->fmax_mhz.ok()) << r->fmax_mhz.reason;
    EXPECT_GT(*r->fmax_mhz.value, 20.0);
    ASSERT_TRUE(r->small_logic_cells.ok()) << r->small_logic_cells.reason;  // the HX1K placement
    ASSERT_TRUE(r->small_fmax_mhz.ok()) << r->small_fmax_mhz.reason;
    EXPECT_FALSE(r->from_cache);
  }
  // The accumulator and its carry: W + 1 flip-flops, so chparam reached the design.
  EXPECT_EQ(*narrow.flip_flops.value, 5.0);
  EXPECT_EQ(*wide.flip_flops.value, 13.0);
  EXPECT_GT(*wide.cells.value, *narrow.cells.value);
  EXPECT_GT(*wide.ice40_luts.value, *narrow.ice40_luts.value);

  const SynthResult again = synthesize(12, s, key);
  EXPECT_TRUE(again.from_cache);
  EXPECT_EQ(*again.cells.value, *wide.cells.value);
  EXPECT_EQ(*again.fmax_mhz.value, *wide.fmax_mhz.value);
  EXPECT_EQ(*again.small_logic_cells.value, *wide.small_logic_cells.value);
}

// Two points that share a parameter set, run at the same time (threads here; processes
// under GNU parallel): one synthesises, the other waits for it and takes the cached result.
TEST_F(Synthesis, PointsSharingASynthesisRunItOnce) {
  const SynthesisSetup s = tiny_setup(dir_.string());
  const std::string key = synthesis_key(s);
  SynthResult a, b;
  std::thread other([&] { a = synthesize(6, s, key); });
  b = synthesize(6, s, key);
  other.join();
  ASSERT_TRUE(a.fmax_mhz.ok() && b.fmax_mhz.ok()) << a.fmax_mhz.reason << b.fmax_mhz.reason;
  EXPECT_NE(a.from_cache, b.from_cache);  // exactly one synthesised
  EXPECT_EQ(*a.ice40_logic_cells.value, *b.ice40_logic_cells.value);
}

TEST_F(Synthesis, AFailingSynthesisKeepsItsReasonInItsRow) {
  SynthesisSetup s = tiny_setup(dir_.string());
  s.rtl_sources = {test::fixture("broken_interp_top.sv")};
  const SynthResult r = synthesize(8, s, synthesis_key(s));
  expect_reason(r.cells, "yosys synth failed: ", "cells");
  EXPECT_NE(r.cells.reason.find("syntax error"), std::string::npos) << r.cells.reason;
  expect_reason(r.flip_flops, "yosys synth failed: ", "flip_flops");
  expect_reason(r.ice40_luts, "yosys synth_ice40 failed: ", "ice40_luts");
  expect_reason(r.ice40_logic_cells, "yosys synth_ice40 (harness) failed: ", "ice40_logic_cells");
  expect_reason(r.fmax_mhz, "yosys synth_ice40 (harness) failed: ", "fmax_mhz");
}

TEST_F(Synthesis, MissingToolsAreStatedNotEstimated) {
  const std::string dir = dir_.string();
  SynthesisSetup no_yosys = tiny_setup(dir);
  no_yosys.yosys = "/nonexistent/yosys";
  const SynthResult a = synthesize(8, no_yosys, synthesis_key(no_yosys));
  for (const Measured* m : {&a.cells, &a.flip_flops, &a.ice40_luts, &a.ice40_logic_cells, &a.fmax_mhz})
    expect_reason(*m, "/nonexistent/yosys not on PATH", "a column");

  SynthesisSetup no_nextpnr = tiny_setup(dir);
  no_nextpnr.nextpnr = "nextpnr-not-installed";
  const std::string key = synthesis_key(no_nextpnr);
  const SynthResult b = synthesize(8, no_nextpnr, key);
  EXPECT_TRUE(b.cells.ok()) << b.cells.reason;
  EXPECT_TRUE(b.ice40_luts.ok()) << b.ice40_luts.reason;
  expect_reason(b.ice40_logic_cells, "nextpnr-not-installed not on PATH", "ice40_logic_cells");
  expect_reason(b.fmax_mhz, "nextpnr-not-installed not on PATH", "fmax_mhz");
  // A tool that never ran says nothing about the design: nothing is cached.
  EXPECT_FALSE(std::filesystem::exists(SynthCache(no_nextpnr.cache_dir, key).path(8)));
}

TEST_F(Synthesis, ADesignTooBigForThePartSaysSoAndKeepsItsCellCount) {
  SynthesisSetup s = tiny_setup(dir_.string());
  s.fpga_top = test::fixture("too_big_fpga_top.sv");
  s.pnr_part_name = "LP384";
  s.pnr_part_args = {"--lp384"};
  const SynthResult r = synthesize(8, s, synthesis_key(s));
  EXPECT_TRUE(r.cells.ok()) << r.cells.reason;  // interp_top itself is measured
  ASSERT_TRUE(r.ice40_logic_cells.ok()) << r.ice40_logic_cells.reason;
  EXPECT_GT(*r.ice40_logic_cells.value, 384.0);
  expect_reason(r.fmax_mhz, "too big for the LP384: ", "fmax_mhz");
  EXPECT_NE(r.fmax_mhz.reason.find(" of 384 logic cells"), std::string::npos) << r.fmax_mhz.reason;
}

TEST_F(SynthCacheFiles, KeepsValuesAndReasonsAndTheKeyFollowsTheContent) {
  const std::string dir = dir_.string();
  SynthResult r;
  r.cells = Measured::of(6026);
  r.flip_flops = Measured::of(776);
  r.ice40_luts = Measured::of(1575);
  r.ice40_logic_cells = Measured::of(9000);
  r.fmax_mhz = Measured::absent("too big for the HX8K: 9000 of 7680 logic cells");
  const SynthCache cache(dir, "k1");
  EXPECT_FALSE(cache.load(16));
  cache.store(16, r);
  const std::optional<SynthResult> back = cache.load(16);
  ASSERT_TRUE(back);
  EXPECT_TRUE(back->from_cache);
  EXPECT_EQ(*back->cells.value, 6026.0);
  EXPECT_EQ(*back->ice40_logic_cells.value, 9000.0);
  EXPECT_EQ(back->fmax_mhz.reason, r.fmax_mhz.reason);
  EXPECT_FALSE(cache.load(17));
  EXPECT_FALSE(SynthCache(dir, "k2").load(16));
  EXPECT_FALSE(SynthCache("", "k1").load(16));  // no directory: no cache

  const std::string f = dir + "/a.sv";
  std::ofstream(f) << "module a; endmodule\n";
  const std::string h1 = content_hash({f}, {"x"});
  EXPECT_EQ(content_hash({f}, {"x"}), h1);
  EXPECT_NE(content_hash({f}, {"y"}), h1);
  std::ofstream(f) << "module a; wire w; endmodule\n";
  EXPECT_NE(content_hash({f}, {"x"}), h1);
}

}  // namespace
}  // namespace ncinterp::sweep
