// `ncinterp play` end to end: the bundled example gives the same report (pulses, final
// position, cycles, path error, timing) with the golden and the RTL engine, and their VCDs
// name the ports identically; the GTKWave save file names only signals the RTL VCD has; a
// bad tape gives one error line, a non-zero exit, a complete error report and no VCD.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>

#include "cli_test.h"
#include "vcd_header.h"

namespace fs = std::filesystem;

namespace {

class PlayCli : public ncinterp::test::CliTest {
 protected:
  int play(const std::string& args) { return run("play " + args); }
};

const std::string kGear = std::string(NCINTERP_EXAMPLES_DIR) + "/gear.nc";

TEST_F(PlayCli, BothEnginesPlayTheExampleIdentically) {
  ASSERT_EQ(play(kGear + " --engine golden --report " + path("g.json") + " --vcd " + path("g.vcd") +
                 " --vcd-from N2 --vcd-to N3"), 0) << stderr_;
  ASSERT_EQ(play(kGear + " --engine rtl --report " + path("r.json") + " --vcd " + path("r.vcd") +
                 " --vcd-from N2 --vcd-to N3"), 0) << stderr_;
  EXPECT_EQ(files(), (std::vector<std::string>{"g.json", "g.vcd", "r.json", "r.vcd"}));
  nlohmann::json g = nlohmann::json::parse(slurp(path("g.json")));
  nlohmann::json r = nlohmann::json::parse(slurp(path("r.json")));
  EXPECT_EQ(g["status"], "ok");
  EXPECT_EQ(g["engine"], "golden");
  EXPECT_EQ(r["engine"], "rtl");
  EXPECT_EQ(g["blocks"], 48);
  EXPECT_EQ(g["final_position_blu"], g["expected_position_blu"]);
  EXPECT_EQ(g["final_position_blu"]["x"], 0);  // the outline closes
  EXPECT_EQ(g["path_within_bound"], true);
  EXPECT_EQ(g["gap_cycles"], 0);
  EXPECT_LT(g["feed"]["worst_time_error_cycles"].get<double>(), 1.0);
  EXPECT_GT(g["pulses"]["x"]["plus"].get<uint64_t>(), 0u);
  for (const char* key : {"blocks", "cycles", "pulses", "final_position_blu", "max_path_error_blu",
                          "status", "gap_cycles", "lead_in_cycles", "feed", "frames_read"})
    EXPECT_EQ(g[key], r[key]) << key;

  const auto gs = ncinterp::test::vcd_signals(path("g.vcd"));
  const auto rs = ncinterp::test::vcd_signals(path("r.vcd"));
  EXPECT_EQ(gs.size(), 23u);  // the interpolator's ports, clock and reset included
  for (const auto& [name, width] : gs) {
    ASSERT_EQ(name.rfind("SystemC.interp.interp_top.", 0), 0u) << name;
    ASSERT_TRUE(rs.count(name)) << name << " is not in the RTL VCD";
    EXPECT_EQ(rs.at(name), width) << name;
  }
  // Same window: the same first and last edge.
  const auto gt = ncinterp::test::vcd_times(path("g.vcd"));
  const auto rt = ncinterp::test::vcd_times(path("r.vcd"));
  ASSERT_FALSE(gt.empty());
  ASSERT_FALSE(rt.empty());
  EXPECT_NEAR(static_cast<double>(gt.front()), static_cast<double>(rt.front()), 500000.0);
  EXPECT_NEAR(static_cast<double>(gt.back()), static_cast<double>(rt.back()), 500000.0);

  // The GTKWave save file opens signals the RTL VCD has, with their widths (GTKWave drops
  // unknown ones silently).
  std::ifstream gtkw(std::string(NCINTERP_EXAMPLES_DIR) + "/../waves/interp.gtkw");
  ASSERT_TRUE(gtkw) << "waves/interp.gtkw missing";
  std::string line;
  int named = 0;
  int filters = 0;
  while (std::getline(gtkw, line)) {
    if (line[0] == '^') {  // "^N waves/NAME.gtkwf": a translate filter file, relative to the root
      const std::string file = line.substr(line.find(' ') + 1);
      EXPECT_TRUE(fs::exists(std::string(NCINTERP_EXAMPLES_DIR) + "/../" + file)) << line;
      ++filters;
      continue;
    }
    if (line.empty() || line[0] == '@' || line[0] == '[' || line[0] == '*' || line[0] == '-') continue;
    const size_t bracket = line.find('[');
    const std::string name = line.substr(0, bracket);
    ASSERT_TRUE(rs.count(name)) << "waves/interp.gtkw names " << name;
    const int width = bracket == std::string::npos ? 1 : std::stoi(line.substr(bracket + 1)) + 1;
    EXPECT_EQ(rs.at(name), width) << "waves/interp.gtkw gives " << line;
    ++named;
  }
  EXPECT_GT(named, 25);
  EXPECT_EQ(filters, 3);  // frame_i as characters, decoder state and error code by name
}

// The bundled circle (four G03 quadrants of radius 50 mm) on both engines: the same report,
// back at the start, every pulse within 1 BLU of the circle (docs/circle-dda.md). In the
// parallel arch at 100 kHz the run is ten times shorter than at the default 1 MHz and no
// block saturates (the serial arch would need 2P = 32 times the clock for that).
TEST_F(PlayCli, TheCircleExampleClosesOnBothEngines) {
  const std::string circle = std::string(NCINTERP_EXAMPLES_DIR) + "/circle_r50.nc";
  const std::string machine = " --arch parallel --clock-hz 100000";
  ASSERT_EQ(play(circle + machine + " --report " + path("g.json")), 0) << stderr_;
  ASSERT_EQ(play(circle + machine + " --engine rtl --report " + path("r.json")), 0) << stderr_;
  nlohmann::json g = nlohmann::json::parse(slurp(path("g.json")));
  nlohmann::json r = nlohmann::json::parse(slurp(path("r.json")));
  EXPECT_EQ(g["status"], "ok");
  EXPECT_EQ(g["blocks"], 4);
  EXPECT_EQ(g["final_position_blu"]["x"], 0);
  EXPECT_EQ(g["final_position_blu"]["y"], 0);
  EXPECT_EQ(g["pulses"]["x"]["plus"], 100000);  // 50 mm out and back on each axis
  EXPECT_EQ(g["pulses"]["y"]["minus"], 100000);
  EXPECT_EQ(g["path_within_bound"], true);
  EXPECT_LE(g["max_path_error_blu"].get<double>(), 1.0);
  EXPECT_EQ(g["feed"]["saturated_blocks"], 0);
  for (const char* key : {"blocks", "cycles", "pulses", "final_position_blu", "max_path_error_blu",
                          "status", "gap_cycles", "feed"})
    EXPECT_EQ(g[key], r[key]) << key;
}

// --accel and --events: both engines play the example ramped and held identically, to the
// same final position as without them, in more clocks; the report names the limit. An
// override without --accel, or an event without a time, is refused before anything is
// written.
TEST_F(PlayCli, RampedAndHeldPlaysAgreeOnBothEnginesAndKeepThePath) {
  const std::string motion = " --accel 500 --events hold@1.0s,resume@1.5s";
  ASSERT_EQ(play(kGear + " --report " + path("p.json")), 0) << stderr_;
  ASSERT_EQ(play(kGear + motion + " --engine golden --report " + path("g.json")), 0) << stderr_;
  ASSERT_EQ(play(kGear + motion + " --engine rtl --report " + path("r.json")), 0) << stderr_;
  const nlohmann::json p = nlohmann::json::parse(slurp(path("p.json")));
  const nlohmann::json g = nlohmann::json::parse(slurp(path("g.json")));
  const nlohmann::json r = nlohmann::json::parse(slurp(path("r.json")));
  EXPECT_EQ(g["accel_mm_s2"], 500.0);
  EXPECT_EQ(g["status"], "ok");
  EXPECT_GT(g["cycles"].get<uint64_t>(), p["cycles"].get<uint64_t>());
  for (const char* key : {"cycles", "pulses", "final_position_blu", "status"}) EXPECT_EQ(g[key], r[key]) << key;
  EXPECT_EQ(g["pulses"], p["pulses"]);
  EXPECT_EQ(g["final_position_blu"], p["final_position_blu"]);

  EXPECT_EQ(play(kGear + " --events override=50@1s --report " + path("e.json")), 1);
  EXPECT_NE(stderr_.find("an override needs --accel"), std::string::npos) << stderr_;
  EXPECT_EQ(play(kGear + " --events hold@1 --report " + path("e.json")), 1);
  EXPECT_NE(stderr_.find("'hold@1' needs a time in seconds"), std::string::npos) << stderr_;
  EXPECT_EQ(files(), (std::vector<std::string>{"g.json", "p.json", "r.json"}));
}

// An E-stop mid-program: both engines stop at its clock with exit 5, status "stopped",
// the error's code and block, the same pulses and position, short of the program's end;
// the VCD of the stopped run is written.
TEST_F(PlayCli, EStopEndsBothEnginesAtItsClockWithExitFive) {
  ASSERT_EQ(play(kGear + " --report " + path("p.json")), 0) << stderr_;
  const std::string stop = " --accel 500 --events estop@1.5s";
  ASSERT_EQ(play(kGear + stop + " --engine golden --report " + path("g.json")), 5) << stderr_;
  EXPECT_NE(stdout_.find("emergency stop in block N"), std::string::npos) << stdout_;
  ASSERT_EQ(play(kGear + stop + " --engine rtl --vcd " + path("r.vcd") + " --report " + path("r.json")), 5)
      << stderr_;
  const nlohmann::json p = nlohmann::json::parse(slurp(path("p.json")));
  const nlohmann::json g = nlohmann::json::parse(slurp(path("g.json")));
  const nlohmann::json r = nlohmann::json::parse(slurp(path("r.json")));
  EXPECT_EQ(g["status"], "stopped");
  EXPECT_EQ(g["error"]["code"], 14);
  EXPECT_EQ(g["error"]["message"], "emergency stop (error code 14)");
  EXPECT_NEAR(g["simulated_seconds"].get<double>(), 1.5, 1e-5);
  for (const char* key : {"cycles", "pulses", "final_position_blu", "status", "error"}) EXPECT_EQ(g[key], r[key]) << key;
  EXPECT_NE(g["final_position_blu"], p["final_position_blu"]);
  EXPECT_EQ(files(), (std::vector<std::string>{"g.json", "p.json", "r.json", "r.vcd"}));
}

// M words: a tape that pauses at M00 with no cycle start ends there with exit 6 and status
// "paused" on both engines; with a later start it plays to its end, at the position of the
// tape without the pause, with the pause's clocks counted apart from the gaps and the tool
// on between M03 and M05.
TEST_F(PlayCli, APauseWithoutCycleStartEndsWithExitSixAndAStartGoesOn) {
  std::ofstream(path("m.nc")) << "%\nG17 G21 G91 G93\nN1 G01 X2.000 Y1.000 F600.000 M03\nN2 M00\n"
                                 "N3 G01 X-1.000 Y2.000 F600.000 M05\nM02\n%\n";
  for (const char* engine : {"golden", "rtl"}) {
    const std::string e = std::string(" --engine ") + engine;
    ASSERT_EQ(play(path("m.nc") + e + " --report " + path("p.json")), 6) << stderr_;
    EXPECT_NE(stdout_.find("paused after block N2"), std::string::npos) << stdout_;
    const nlohmann::json p = nlohmann::json::parse(slurp(path("p.json")));
    EXPECT_EQ(p["status"], "paused") << engine;
    EXPECT_EQ(p["final_position_blu"]["x"], 2000) << engine;
    ASSERT_EQ(play(path("m.nc") + e + " --events start@1s --report " + path("s.json")), 0) << stderr_;
    const nlohmann::json s = nlohmann::json::parse(slurp(path("s.json")));
    EXPECT_EQ(s["status"], "ok") << engine;
    EXPECT_EQ(s["final_position_blu"]["x"], 1000) << engine;
    EXPECT_EQ(s["final_position_blu"]["y"], 3000) << engine;
    EXPECT_GT(s["paused_cycles"].get<uint64_t>(), 500000u) << engine;
    EXPECT_LT(s["gap_cycles"].get<uint64_t>(), 1000u) << engine;
    EXPECT_GT(s["tool_on_cycles"].get<uint64_t>(), s["paused_cycles"].get<uint64_t>()) << engine;
  }
}

TEST_F(PlayCli, BadTapeGivesOneLineAnErrorReportAndNoVcd) {
  std::ifstream in(kGear);
  std::stringstream ss;
  ss << in.rdbuf();
  std::string text = ss.str();
  const size_t at = text.find("N3 ") + 10;  // "N3 G01 X-2.116": the '.' -> ','
  ASSERT_EQ(text[at], '.');
  text[at] = ',';
  std::ofstream(path("bad.nc")) << text;
  EXPECT_EQ(play(path("bad.nc") + " --vcd " + path("bad.vcd") + " --report " + path("bad.json")), 1);
  // The ',' ends the word "X-2", which is checked first: a malformed number (no point),
  // reported at the X, before the ',' itself (an unknown character) is looked at.
  const std::string expect_line = path("bad.nc") + ": block N3, offset " +
                                  std::to_string(text.find("N3 ") + 7) + ": malformed number";
  EXPECT_EQ(stderr_.rfind(expect_line, 0), 0u) << stderr_;
  EXPECT_EQ(std::count(stderr_.begin(), stderr_.end(), '\n'), 1) << stderr_;
  EXPECT_EQ(files(), (std::vector<std::string>{"bad.json", "bad.nc"}));
  const nlohmann::json j = nlohmann::json::parse(slurp(path("bad.json")));
  EXPECT_EQ(j["status"], "error");
  EXPECT_EQ(j["error"]["block"], 3);
  EXPECT_EQ(j["error"]["offset"], text.find("N3 ") + 7);
  EXPECT_EQ(j["blocks"], 2);  // N1 and N2 played, nothing of N3
  EXPECT_EQ(j["reader_agrees"], true);
}

TEST_F(PlayCli, CycleLimitIsAnErrorWithoutVcd) {
  EXPECT_EQ(play(kGear + " --max-cycles 100000 --vcd " + path("l.vcd") + " --report " + path("l.json")), 1);
  EXPECT_NE(stderr_.find("cycle limit"), std::string::npos) << stderr_;
  EXPECT_EQ(files(), (std::vector<std::string>{"l.json"}));
  const nlohmann::json j = nlohmann::json::parse(slurp(path("l.json")));
  EXPECT_EQ(j["status"], "error");
  EXPECT_EQ(j["cycles"], 100000);
  EXPECT_TRUE(j["vcd"]["file"].is_null());
}

TEST_F(PlayCli, UnreadableInputNamesTheFile) {
  EXPECT_EQ(play(path("none.tape") + " --report " + path("r.json")), 1);
  EXPECT_NE(stderr_.find(path("none.tape")), std::string::npos) << stderr_;
  std::ofstream(path("latin1.nc")) << "%\nN1 G01 X1.000 F1.000 (\xE9)\nM02\n%\n";
  EXPECT_EQ(play(path("latin1.nc") + " --report " + path("r.json")), 1);
  EXPECT_NE(stderr_.find(path("latin1.nc") + ": offset 24: byte 0xE9"), std::string::npos) << stderr_;
  EXPECT_EQ(files(), (std::vector<std::string>{"latin1.nc"}));
}

TEST_F(PlayCli, BadOptionsWriteNothing) {
  EXPECT_NE(play(kGear + " --vcd " + path("w.vcd") + " --vcd-from X5"), 0);
  EXPECT_NE(play(kGear + " --vcd " + path("w.vcd") + " --vcd-from N999"), 0);
  EXPECT_NE(stderr_.find("N999"), std::string::npos) << stderr_;
  EXPECT_NE(play(kGear + " --vcd " + path("w.vcd") + " --vcd-from N6 --vcd-to N4"), 0);
  EXPECT_NE(play(kGear + " --engine fpga"), 0);
  EXPECT_NE(play(kGear + " --vcd-from 5"), 0);  // a window without --vcd
  EXPECT_TRUE(files().empty());
}

TEST_F(PlayCli, VcdThatIsADirectoryFailsBeforeTheRunAndLeavesNothing) {
  fs::create_directory(path("waves"));
  EXPECT_EQ(play(kGear + " --vcd " + path("waves") + " --report " + path("r.json")), 1);
  EXPECT_NE(stderr_.find("is a directory"), std::string::npos) << stderr_;
  EXPECT_EQ(stdout_, "");  // refused before the simulation, not after it
  EXPECT_EQ(play(kGear + " --vcd " + path("nodir/w.vcd")), 1);
  EXPECT_EQ(files(), std::vector<std::string>{"waves"});
  EXPECT_TRUE(fs::is_empty(path("waves")));
}

TEST_F(PlayCli, UsageErrorsExitOne) {
  EXPECT_EQ(play(kGear + " --engine fpga"), 1);
  EXPECT_EQ(std::count(stderr_.begin(), stderr_.end(), '\n'), 1) << stderr_;
  EXPECT_EQ(play(kGear + " --clock-hz fast"), 1);
  EXPECT_EQ(play(""), 1);  // the tape is required
}

}  // namespace
