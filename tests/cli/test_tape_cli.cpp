// `ncinterp tape` end to end: every example input kind with every method and both arc
// modes makes a tape that the project's tape reader reads, whose increments close on the
// contour's end, whose report is complete and within the tolerance, and which
// `ncinterp play` plays to the end at the expected position; bad input or options give one
// line naming the file and line, a non-zero exit and no output file.
#include <gtest/gtest.h>

#include <sys/stat.h>

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <nlohmann/json.hpp>

#include "cli_test.h"
#include "inputs/contour_inputs.h"
#include "tape/tape.h"

namespace fs = std::filesystem;

namespace ncinterp::test {
namespace {

const std::string kExamples = example("contours");

// A file name as a GoogleTest parameter name (letters and digits only).
std::string test_name_of(std::string name) {
  for (char& ch : name)
    if (!std::isalnum(static_cast<unsigned char>(ch))) ch = '_';
  return name;
}

class TapeCli : public CliTest {
 protected:
  static nlohmann::json json_of(const std::string& p) { return nlohmann::json::parse(slurp(p)); }
};

// ---- every input kind, every method, both arc modes ----------------------------------

class TapeCliExamples : public TapeCli, public ::testing::WithParamInterface<const char*> {};

TEST_P(TapeCliExamples, EveryMethodAndArcModeMakesAPlayableTape) {
  const std::string input = kExamples + "/" + GetParam();
  const firststage::Contour contour = firststage::read_contour(input, {});
  const double tol = 0.01, blu = 0.001;
  const int64_t end_x = std::llround(contour.end().x / blu), end_y = std::llround(contour.end().y / blu);
  for (int method = 1; method <= 3; ++method) {
    std::string chords_text;
    for (const std::string arcs : {"chords", "circle"}) {
      SCOPED_TRACE(std::string(GetParam()) + " --method " + std::to_string(method) + " --arcs " + arcs);
      // Frames for chord tapes, plain text for arc tapes: both writer paths.
      const std::string out = path(arcs == "chords" ? "t.tape" : "t.nc"), report = path("r.json");
      ASSERT_EQ(run("tape " + input + " -o " + out + " --method " + std::to_string(method) +
                    " --arcs " + arcs + " --feed 6000 --report " + report), 0) << stderr_;
      EXPECT_EQ(stderr_, "");
      const nlohmann::json r = json_of(report);

      // The project's reader reads it; it checks every arc block as the interpolator's
      // decoder does (quadrant, end on the circle, registers).
      tape::Format format;
      const tape::Program p = tape::parse_frames(tape::load_frames(out), format);
      EXPECT_EQ(r["blocks"].get<size_t>(), p.blocks.size());
      EXPECT_EQ(r["tape"]["frames"].get<size_t>(), fs::file_size(out));
      EXPECT_EQ(r["tape"]["bytes"].get<size_t>(), fs::file_size(out));
      // Closure: the increments end on the contour's end point (tape start + sum).
      const auto start = r["start_mm"];
      int64_t x = std::llround(start[0].get<double>() / blu), y = std::llround(start[1].get<double>() / blu);
      bool has_arcs = false;
      for (const tape::Block& b : p.blocks) {
        x += b.dx;
        y += b.dy;
        has_arcs |= tape::is_arc(b.motion);
      }
      EXPECT_EQ(x, end_x);
      EXPECT_EQ(y, end_y);
      EXPECT_EQ(has_arcs, r["arc_blocks"].get<long>() > 0);
      // The report: within the tolerance minus the interpolator's budget, every figure there.
      EXPECT_LE(r["max_deviation_mm"].get<double>(), tol - blu + 1e-6);
      EXPECT_GT(r["max_deviation_mm"].get<double>(), has_arcs ? 0.0 : 0.5 * tol);
      long chords = 0;
      for (const auto& e : r["chords_per_element"]) chords += e["chords"].get<long>();
      EXPECT_EQ(chords, r["chords"].get<long>());
      for (const char* key : {"input", "method", "tol_mm", "blu_mm", "width", "blocks", "chords_per_element",
                              "max_deviation_mm", "tape", "planner", "time_s"})
        EXPECT_TRUE(r.contains(key)) << key;
      EXPECT_EQ(r["method"], method);

      // Inputs without circular arcs give the same tape in both modes.
      const std::string text = slurp(out);
      if (arcs == "chords") {
        for (char& ch : chords_text = text) ch = static_cast<char>(ch & 0x7f);
      } else if (!has_arcs) {
        EXPECT_EQ(text, chords_text);
        continue;  // played already
      }

      // It plays: to the end, at the expected position, every block.
      ASSERT_EQ(run("play " + out + " --reader-cps 1e6 --clock-hz 1e5 --report " + path("p.json")), 0)
          << stderr_;
      const nlohmann::json played = json_of(path("p.json"));
      EXPECT_EQ(played["status"], "ok");
      EXPECT_EQ(played["blocks"].get<size_t>(), p.blocks.size());
      EXPECT_EQ(played["final_position_blu"]["x"].get<int64_t>(),
                end_x - std::llround(start[0].get<double>() / blu));
      EXPECT_EQ(played["final_position_blu"]["y"].get<int64_t>(),
                end_y - std::llround(start[1].get<double>() / blu));
    }
  }
}

INSTANTIATE_TEST_SUITE_P(Examples, TapeCliExamples,
                         ::testing::Values("circle_r50.json", "reference_table.json", "profile.json", "part.nc",
                                           "naca2412_selig.dat", "naca2412_lednicer.dat"),
                         [](const auto& info) { return test_name_of(info.param); });

TEST_F(TapeCli, CutterOffsetTapePlaysAndClosesEachChain) {
  const std::string input = kExamples + "/part.nc";
  ASSERT_EQ(run("tape " + input + " -o " + path("t.tape") +
                " --cutter-radius 3 --side right --feed 6000 --report " + path("r.json")), 0) << stderr_;
  const nlohmann::json r = json_of(path("r.json"));
  // The outline starts at its corner (0, 0), a convex 90-degree corner: the offset lines
  // meet at (-3, -3).
  EXPECT_DOUBLE_EQ(r["start_mm"][0].get<double>(), -3.0);
  EXPECT_DOUBLE_EQ(r["start_mm"][1].get<double>(), -3.0);
  ASSERT_EQ(run("play " + path("t.tape") + " --reader-cps 1e6 --clock-hz 1e5 --report " + path("p.json")), 0)
      << stderr_;
  const nlohmann::json played = json_of(path("p.json"));
  EXPECT_EQ(played["status"], "ok");
  // It ends where the hole's offset chain started: the hole (centre (40, 35), radius 10,
  // clockwise) is cut from inside at radius 7, from the offset vertex near (47, 35) (the
  // two chords meeting at (50, 35) differ a little, so the vertex is a little off the axis).
  const double x = -3.0 + played["final_position_blu"]["x"].get<int64_t>() * 0.001;
  const double y = -3.0 + played["final_position_blu"]["y"].get<int64_t>() * 0.001;
  EXPECT_NEAR(std::hypot(x - 40.0, y - 35.0), 7.0, 0.01);
  EXPECT_NEAR(x, 47.0, 0.05);
  EXPECT_NEAR(y, 35.0, 0.05);
}

TEST_F(TapeCli, TextAndFrameTapesHoldTheSameProgram) {
  const std::string input = kExamples + "/reference_table.json";
  ASSERT_EQ(run("tape " + input + " -o " + path("a.tape")), 0) << stderr_;
  ASSERT_EQ(run("tape " + input + " -o " + path("a.nc")), 0) << stderr_;
  std::string frames = slurp(path("a.tape"));
  for (const char ch : frames) EXPECT_TRUE(tape::has_even_parity(static_cast<uint8_t>(ch)));
  for (char& ch : frames) ch = static_cast<char>(ch & 0x7f);
  EXPECT_EQ(frames, slurp(path("a.nc")));
  EXPECT_EQ(frames.rfind("%\n", 0), 0u);
  EXPECT_NE(frames.find("G17 G21 G91 G93"), std::string::npos);
  EXPECT_EQ(files(), (std::vector<std::string>{"a.nc", "a.tape"}));
}

// ---- bad input: one line naming file and line, exit 1, no output ----------------------

struct BadCase {
  const char* name;      // input file name (its extension picks the reader)
  const char* text;      // content (nullptr: the file does not exist)
  const char* expected;  // the start of the one-line message after the directory
};

// ctest lists the case by its file name.
void PrintTo(const BadCase& c, std::ostream* os) { *os << c.name; }

class TapeCliBadInput : public TapeCli, public ::testing::WithParamInterface<BadCase> {};

TEST_P(TapeCliBadInput, OneLineNamingFileAndLineNoOutput) {
  const BadCase& c = GetParam();
  if (c.text) write(c.name, c.text);
  EXPECT_EQ(run("tape " + path(c.name) + " -o " + path("out.tape") + " --report " + path("r.json")), 1);
  EXPECT_EQ(stdout_, "");
  ASSERT_FALSE(stderr_.empty());
  EXPECT_EQ(stderr_.find('\n'), stderr_.size() - 1) << "more than one line: " << stderr_;
  EXPECT_EQ(stderr_.rfind(path(c.name) + ":" + c.expected, 0), 0u) << stderr_;
  EXPECT_EQ(files(), c.text ? std::vector<std::string>{c.name} : std::vector<std::string>{});
}

INSTANTIATE_TEST_SUITE_P(
    Inputs, TapeCliBadInput,
    ::testing::Values(
        BadCase{"syntax.json", "{\n  \"start\": [0, 0],\n  \"segments\": [ {\"type\": \"line\" \"to\": [1, 0]} ]\n}\n",
                "3: invalid JSON"},
        // nlohmann throws out_of_range, not parse_error, for a number beyond a double.
        BadCase{"overflow.json", "{\n  \"start\": [0, 0],\n  \"segments\": [1E999]\n}\n",
                "3: invalid JSON: number out of range '1E999'"},
        BadCase{"type.json",
                "{\n  \"start\": [0, 0],\n  \"segments\": [\n    {\"type\": \"line\", \"to\": [1, 0]},\n"
                "    {\"type\": \"spiral\"}\n  ]\n}\n",
                "5: unknown segment type \"spiral\""},
        BadCase{"arc.json",
                "{\"start\": [10, 0],\n \"segments\": [\n  {\"type\": \"arc\", \"center\": [0, 0], \"to\": [0, 11], "
                "\"direction\": \"ccw\"}]}\n",
                "3: arc end is 1 mm off the circle"},
        BadCase{"table.json",
                "{\"start\": [0, 1],\n \"segments\": [\n  {\"type\": \"table\", \"x0\": 0, \"h\": 1, \"y\": [1, 2, 3]}]}\n",
                "3: table needs \"y\": at least 4 ordinates"},
        BadCase{"word.nc", "%\nG21 G90\nG1 X10 Y0 F100\nG1 X10 Y\n", "4: word Y needs a number"},
        BadCase{"comp.ngc", "G21\nG0 X0 Y0\nG41 D1 G1 X10 Y0\n", "3: G41: cutter compensation"},
        BadCase{"plane.gcode", "G18\nG1 X1 Y1\n", "1: G18: only the XY plane"},
        BadCase{"sub.tap", "G21\no100 sub\n", "2: O-word 'o100 sub' (a subroutine)"},
        BadCase{"arcr.nc", "G1 X0 Y0\nG2 X10 Y0 R2\n", "2: arc radius R2 is 3 mm shorter than half the distance"},
        BadCase{"num.dat", "AIRFOIL\n1.0 0.0\n0.5 0.05\n0.0 0.0\n0.5 abc\n1.0 0.0\n", "5: 'abc' is not a number"},
        BadCase{"lednicer.dat", "AIRFOIL\n3. 3.\n\n0 0\n0.5 0.05\n1 0\n\n0 0\n0.5 -0.05\n", "9: Lednicer header announces 3 + 3 points"},
        // A count beyond any integer (the airfoil fuzzer; UBSan before the fix).
        BadCase{"count.dat", "AIRFOIL\n1e38 3.\n0 0\n0.5 0.05\n1 0\n", "5: Lednicer header announces 1e+38 + 3 points"},
        BadCase{"huge.json", "{\"start\": [0, 0],\n \"segments\": [\n  {\"type\": \"line\", \"to\": [1e30, 0]}]}\n",
                "3: coordinate out of range"},
        BadCase{"far.nc", "G21 G90\nG1 X0 Y0 F100\nG1 X1000000000 Y0\n", "3: coordinate out of range"},
        // A centre 5.6e15 mm away: a double holds such a circle's points to about 1 mm.
        BadCase{"farcentre.nc", "G21 G90\nG1 X45 Y70 F100\nG2 X25 Y70 I-10 J5555555555555550\n",
                "3: arc centre out of range"},
        BadCase{"tiny.json", "{\"start\": [0, 0],\n \"segments\": [\n  {\"type\": \"line\", \"to\": [0.0002, 0]}]}\n",
                "0: no cutting move of 1 BLU or more"},
        BadCase{"c2um.nc", "G21 G90\nG0 X0.002 Y0\nG3 X0.002 Y0 I-0.002 J0 F100\nM2\n",
                "3: full circle of radius 0.002 mm is within the tolerance"},
        BadCase{"contour.txt", "G1 X1\n", "0: unknown input kind '.txt'"},
        BadCase{"missing.json", nullptr, "0: cannot open the file"}),
    [](const auto& info) { return test_name_of(info.param.name); });

// --accel plans the feed: the report gives the cycle time without a ramp, at exact stop
// and in continuous mode for each look-ahead, each no faster than the next; `check` plays
// the tape at exact stop in the planned time (from its first block's load on).
TEST_F(TapeCli, TheFeedPlanForetellsWhatCheckPlays) {
  const std::string input = kExamples + "/naca2412_selig.dat";
  ASSERT_EQ(run("tape " + input + " -o " + path("a.tape") + " --accel 500 --report " + path("r.json")), 0)
      << stderr_;
  EXPECT_NE(stdout_.find("cycle time at 500 mm/s^2 (12 MHz board)"), std::string::npos) << stdout_;
  const nlohmann::json plan = json_of(path("r.json"))["feed_plan"];
  const double exact = plan["exact_stop_seconds"];
  double previous = exact;
  ASSERT_EQ(plan["continuous_planned_only"].size(), 4u);
  for (const nlohmann::json& c : plan["continuous_planned_only"]) {
    EXPECT_LE(c["seconds"].get<double>(), previous) << c;
    previous = c["seconds"];
  }
  EXPECT_EQ(plan["continuous_planned_only"][3]["lookahead_blocks"], "all");
  EXPECT_GT(previous, plan["programmed_seconds"].get<double>());
  ASSERT_EQ(run("check " + path("a.tape") + " --accel 500 --clock-hz 12e6 --report " + path("c.json")), 0)
      << stderr_;
  const nlohmann::json played = json_of(path("c.json"))["feed_plan"];
  EXPECT_NEAR(played["planned_seconds"].get<double>(), exact, 1e-9);
  EXPECT_NEAR(played["played_seconds"].get<double>(), exact, 1e-3 * exact);
}

// A small arc at a high feed is too fast for the acceleration limit (v^2 / R above it):
// `check --accel` fails it on the centripetal rule. `tape --accel` feeds each such arc at
// sqrt(A R), and the same program then passes; its lines keep --feed.
TEST_F(TapeCli, AccelFeedsSmallArcsWithinTheCentripetalLimit) {
  const std::string input = kExamples + "/cam/estlcam_bolt_holes.nc";
  const std::string check = " --contour " + input + " --accel 500 --clock-hz 12e6 --report " + path("c.json");
  ASSERT_EQ(run("tape " + input + " -o " + path("fast.nc") + " --arcs circle --feed 6000 --report " + path("f.json")), 0)
      << stderr_;
  EXPECT_EQ(json_of(path("f.json"))["arcs_slowed_to_accel"], 0);
  EXPECT_EQ(run("check " + path("fast.nc") + check), 2) << stdout_;
  EXPECT_NE(stdout_.find("the arc's centripetal acceleration v^2 / R is at least"), std::string::npos) << stdout_;
  ASSERT_EQ(run("tape " + input + " -o " + path("slow.nc") + " --arcs circle --feed 6000 --accel 500 --report " +
                path("s.json")), 0) << stderr_;
  const nlohmann::json r = json_of(path("s.json"));
  EXPECT_GT(r["arcs_slowed_to_accel"].get<long>(), 0);
  EXPECT_LT(r["arcs_slowed_to_accel"].get<long>(), r["arc_blocks"].get<long>() + 1);
  EXPECT_NE(stdout_.find("arc block(s) fed below --feed, at sqrt(A R)"), std::string::npos) << stdout_;
  ASSERT_EQ(run("check " + path("slow.nc") + check), 0) << stdout_;
  const nlohmann::json c = json_of(path("c.json"));
  EXPECT_GT(c["acceleration"]["max_centripetal_mm_s2"].get<double>(), 250.0);
  // The lines of both tapes are the same blocks.
  const tape::Program fast = tape::parse_frames(tape::load_frames(path("fast.nc")), tape::Format{});
  const tape::Program slow = tape::parse_frames(tape::load_frames(path("slow.nc")), tape::Format{});
  ASSERT_EQ(fast.blocks.size(), slow.blocks.size());
  for (size_t i = 0; i < fast.blocks.size(); ++i)
    if (!tape::is_arc(fast.blocks[i].motion)) EXPECT_EQ(fast.blocks[i].feed, slow.blocks[i].feed) << i;
    else EXPECT_LE(slow.blocks[i].feed, fast.blocks[i].feed) << i;
}

// --tool switches the tool around every run of cuts; --pierce-delay S puts the M03 on a
// block that dwells S seconds at rest before the run (a G01 without motion, F = 60 / S per
// minute). The check passes (the tool rule included) and the run is S longer per pierce.
TEST_F(TapeCli, APierceDelayDwellsWithTheToolOnBeforeEachRunOfCuts) {
  const std::string input = kExamples + "/cam/laser_lightburn.gcode";
  ASSERT_EQ(run("tape " + input + " -o " + path("t.nc") + " --tool"), 0) << stderr_;
  ASSERT_EQ(run("tape " + input + " -o " + path("p.nc") + " --tool --pierce-delay 0.25"), 0) << stderr_;
  const std::string text = slurp(path("p.nc"));
  size_t pierces = 0;
  for (size_t at = text.find("M03"); at != std::string::npos; at = text.find("M03", at + 1)) {
    const size_t start = text.rfind('\n', at) + 1;
    EXPECT_NE(text.substr(start, at - start).find("G01 X0.000 Y0.000 F240.000"), std::string::npos)
        << text.substr(start, at - start);
    ++pierces;
  }
  EXPECT_EQ(pierces, 2u);
  double seconds[2];
  for (int k = 0; k < 2; ++k) {
    ASSERT_EQ(run("check " + path(k ? "p.nc" : "t.nc") + " --clock-hz 12e6 --report " + path("c.json")), 0)
        << stdout_ << stderr_;
    seconds[k] = json_of(path("c.json"))["cycle_seconds"];
  }
  EXPECT_NEAR(seconds[1] - seconds[0], 0.25 * pierces, 1e-6);
  EXPECT_EQ(run("tape " + input + " -o " + path("q.nc") + " --pierce-delay 0.25"), 1);
  EXPECT_NE(stderr_.find("--pierce-delay requires --tool"), std::string::npos) << stderr_;
}

TEST_F(TapeCli, BadOptionsOneLineNoOutput) {
  const std::string input = kExamples + "/circle_r50.json";
  const std::string out = " -o " + path("out.tape") + " --report " + path("r.json");
  EXPECT_EQ(run("tape " + input + out + " --tol 0.0015"), 1);  // < 1 BLU left after the budget
  EXPECT_EQ(stderr_.rfind("ncinterp tape: --tol leaves less than 1 BLU", 0), 0u) << stderr_;
  EXPECT_EQ(run("tape " + input + out + " --blu 0.002"), 1);
  EXPECT_EQ(stderr_.rfind("ncinterp tape: --blu must be", 0), 0u) << stderr_;
  EXPECT_EQ(run("tape " + input + out + " --arcs circle --cutter-radius 2"), 1);
  EXPECT_EQ(stderr_.rfind("ncinterp tape: the cutter offset works on chords", 0), 0u) << stderr_;
  EXPECT_EQ(run("tape " + input + " -o " + path("no/such/dir/out.tape")), 1);
  EXPECT_NE(stderr_.find("no/such/dir/out.tape"), std::string::npos) << stderr_;
  EXPECT_NE(run("tape " + input + out + " --method 4"), 0);  // CLI11 refuses it
  EXPECT_NE(run("tape " + input), 0);                        // -o is required
  EXPECT_EQ(files(), std::vector<std::string>{});
}

// ---- outputs: never destroy an input, a link or a stream; all outputs or none ----------

TEST_F(TapeCli, OutputThatIsTheInputIsRefusedAndTheInputKept) {
  write("part.nc", slurp(kExamples + "/part.nc"));
  const std::string before = slurp(path("part.nc"));
  EXPECT_EQ(run("tape " + path("part.nc") + " -o " + path("part.nc")), 1);
  EXPECT_NE(stderr_.find("is the input"), std::string::npos) << stderr_;
  fs::create_symlink("part.nc", path("alias.nc"));
  EXPECT_EQ(run("tape " + path("part.nc") + " -o " + path("x.tape") + " --report " + path("alias.nc")), 1);
  EXPECT_EQ(slurp(path("part.nc")), before);
  EXPECT_EQ(files(), (std::vector<std::string>{"alias.nc", "part.nc"}));
}

TEST_F(TapeCli, BadReportPathLeavesNoTape) {
  const std::string input = kExamples + "/circle_r50.json";
  EXPECT_EQ(run("tape " + input + " -o " + path("t.tape") + " --report " + path("nodir/r.json")), 1);
  EXPECT_NE(stderr_.find("nodir/r.json"), std::string::npos) << stderr_;
  fs::create_directory(path("adir"));
  EXPECT_EQ(run("tape " + input + " -o " + path("t.tape") + " --report " + path("adir")), 1);
  EXPECT_NE(stderr_.find("is a directory"), std::string::npos) << stderr_;
  EXPECT_EQ(files(), std::vector<std::string>{"adir"});
}

TEST_F(TapeCli, SymlinkOutputWritesItsTargetAndStaysALink) {
  const std::string input = kExamples + "/circle_r50.json";
  write("real.tape", "old");
  fs::create_symlink("real.tape", path("link.tape"));
  ASSERT_EQ(run("tape " + input + " -o " + path("link.tape")), 0) << stderr_;
  EXPECT_TRUE(fs::is_symlink(path("link.tape")));
  EXPECT_GT(fs::file_size(path("real.tape")), 100u);
  EXPECT_EQ(files(), (std::vector<std::string>{"link.tape", "real.tape"}));
}

TEST_F(TapeCli, DashAndDevNullAreStreamed) {
  const std::string input = kExamples + "/circle_r50.json";
  ASSERT_EQ(run("tape " + input + " -o - --report /dev/null"), 0) << stderr_;
  EXPECT_EQ(stdout_.rfind("%", 0), 0u) << stdout_.substr(0, 80);  // the plain-text tape itself
  EXPECT_NE(stderr_.find("blocks"), std::string::npos) << stderr_;  // the summary moved to stderr
  struct stat st {};
  ASSERT_EQ(::stat("/dev/null", &st), 0);
  EXPECT_TRUE(S_ISCHR(st.st_mode));
  EXPECT_TRUE(files().empty());
}

// Every CAM-style file a 2-axis machine can cut (examples/contours/cam/): taped with its
// warnings (ignored words; feed moves taped as traverses; words after the end), one pass per
// depth in the report, traverses as G00 blocks; and `check` passes on the tape, also with
// the feed ramp and the tool words on both archs.
struct CamFile {
  const char* name;
  int warnings;  // warning lines on stderr
  int passes;
};

void PrintTo(const CamFile& k, std::ostream* os) { *os << k.name; }

class TapeCliCam : public TapeCli, public ::testing::WithParamInterface<CamFile> {};

TEST_P(TapeCliCam, TapesAndPassesTheCheck) {
  const CamFile& k = GetParam();
  const std::string input = kExamples + "/cam/" + k.name;
  ASSERT_EQ(run("tape " + input + " -o " + path("t.tape") + " --report " + path("r.json")), 0) << stderr_;
  EXPECT_EQ(std::count(stderr_.begin(), stderr_.end(), '\n'), k.warnings) << stderr_;
  size_t at = 0;
  for (int w = 0; w < k.warnings; ++w, at = stderr_.find('\n', at) + 1)
    EXPECT_EQ(stderr_.compare(at, input.size() + 11, input + ": warning: "), 0) << stderr_;
  const nlohmann::json r = json_of(path("r.json"));
  ASSERT_EQ(r["passes"].size(), static_cast<size_t>(k.passes)) << r["passes"].dump();
  long blocks = 0, traverses = 0;
  for (const auto& p : r["passes"]) {
    blocks += p["blocks"].get<long>();
    traverses += p["traverse_blocks"].get<long>();
    EXPECT_GT(p["cut_mm"].get<double>(), 0.0);
  }
  EXPECT_EQ(blocks, r["blocks"].get<long>());
  EXPECT_EQ(traverses, r["traverse_blocks"].get<long>());
  const tape::Program prog = tape::parse_frames(tape::load_frames(path("t.tape")), tape::Format{});
  long g00 = 0;
  for (const tape::Block& b : prog.blocks) g00 += tape::is_rapid(b.motion);
  EXPECT_EQ(g00, traverses);
  EXPECT_GT(g00, 0);
  ASSERT_EQ(run("check " + path("t.tape") + " --contour " + input + " --reader-cps 100000 --report " +
                path("c.json")), 0) << stdout_ << stderr_;
  const nlohmann::json c = json_of(path("c.json"));
  EXPECT_EQ(c["status"], "pass");
  EXPECT_LE(c["total_error"]["max_mm"].get<double>(), 0.01);
  EXPECT_EQ(c["total_error"]["rapid_blocks"].get<long>(), traverses);
  // With the feed ramp and the tool words (--tool), on both archs: every rule holds, the
  // acceleration and tool rules among them, and the machine ends where it ends without the
  // ramp.
  ASSERT_EQ(run("tape " + input + " -o " + path("tool.tape") + " --tool"), 0) << stderr_;
  for (const char* arch : {"serial", "parallel"}) {
    SCOPED_TRACE(arch);
    ASSERT_EQ(run("check " + path("tool.tape") + " --contour " + input + " --reader-cps 100000 --accel 500 --arch " +
                  arch + " --report " + path("a.json")), 0) << stdout_ << stderr_;
    const nlohmann::json a = json_of(path("a.json"));
    EXPECT_EQ(a["status"], "pass");
    EXPECT_LE(a["acceleration"]["worst_of_limit_and_allowance"].get<double>(), 1.0);
    EXPECT_EQ(a["final_position"], c["final_position"]);
  }
}

INSTANTIATE_TEST_SUITE_P(
    Cam, TapeCliCam,
    ::testing::Values(CamFile{"fusion360_profile.nc", 1, 2}, CamFile{"freecad_profile.ngc", 1, 1},
                      CamFile{"estlcam_profile.nc", 2, 1}, CamFile{"depth_passes_minimal.nc", 0, 2},
                      CamFile{"fusion360_passes_tabs.nc", 2, 3}, CamFile{"freecad_grbl_disc.gcode", 2, 2},
                      CamFile{"estlcam_bolt_holes.nc", 2, 2}, CamFile{"pcb_gcode_etch.tap", 1, 1},
                      CamFile{"plasma_mach3_flange.tap", 1, 1}, CamFile{"laser_lightburn.gcode", 1, 1},
                      CamFile{"linuxcnc_inch_r_arcs.ngc", 2, 1}),
    [](const auto& info) { return test_name_of(info.param.name); });

// The CAM-style files that cannot be taped: one line naming the file, the line and the
// reason (with what to change in the post), exit 1, no output.
TEST_F(TapeCli, CamRefusalsNameFileLineAndReason) {
  const std::string dir = kExamples + "/cam/refused/";
  const std::pair<const char*, const char*> cases[] = {
      {"fusion360_vertical_leadin.nc", ":17: G18: only the XY plane (G17) is supported"},
      {"linuxcnc_subroutine.ngc", ":3: O-word 'o100 sub' (a subroutine) is not supported"},
      {"plasmac_parameters.ngc", ":4: word F at column 1 takes a parameter"},
      {"router_vfd_header.nc", ":1: '%' line with text ('% vfd enable')"},
  };
  for (const auto& [file, says] : cases) {
    SCOPED_TRACE(file);
    EXPECT_EQ(run("tape " + dir + file + " -o " + path("t.tape") + " --report " + path("r.json")), 1);
    EXPECT_EQ(stderr_.rfind(dir + file + says, 0), 0u) << stderr_;
    EXPECT_EQ(std::count(stderr_.begin(), stderr_.end(), '\n'), 1) << stderr_;
    EXPECT_TRUE(files().empty());
  }
}

// The minimal case: `tape` wrote 0.0000 mm and `check` failed by 10 mm, measuring
// the traverses along the finished line as cuts. The traverses are G00 now.
TEST_F(TapeCli, TwoDepthsWithTabsPassTheCheck) {
  write("tabs.nc", "G21 G90\nG0 Z5\nG0 X0 Y0\nG1 Z-1 F100\nG1 X60\nG1 Z-2\nG1 X55\nG1 Z-1\nG1 X35\n"
                   "G1 Z-2\nG1 X0\nG0 Z5\nM2\n");
  ASSERT_EQ(run("tape " + path("tabs.nc") + " -o " + path("t.nc")), 0) << stderr_;
  EXPECT_EQ(slurp(path("t.nc")),
            "%\nG17 G21 G91 G93\n"
            "N1 G01 X60.000 Y0.000 F16.666\n"
            "N2 G00 X-5.000 Y0.000\n"
            "N3 G01 X-20.000 Y0.000 F50.000\n"
            "N4 G00 X25.000 Y0.000\n"
            "N5 G01 X-5.000 Y0.000 F200.000\n"
            "N6 G00 X-20.000 Y0.000\n"
            "N7 G01 X-35.000 Y0.000 F28.571\n"
            "M02\n%\n");
  EXPECT_NE(stdout_.find("pass 1 at Z-1: 3 blocks from N1 (1 traverses), 80.000 mm cut"), std::string::npos) << stdout_;
  EXPECT_NE(stdout_.find("pass 2 at Z-2: 4 blocks from N4 (2 traverses), 40.000 mm cut"), std::string::npos) << stdout_;
  ASSERT_EQ(run("check " + path("t.nc") + " --contour " + path("tabs.nc") + " --reader-cps 100000"), 0)
      << stdout_ << stderr_;
}

TEST_F(TapeCli, PointBeyondThePositionCounterIsRefusedBeforeTheWork) {
  // Within the readers' 1e6 mm but beyond the 32-bit position counter at a 1 nm BLU
  // (+-2147 mm): refused naming the line, before 5000 mm are split into 76 000 blocks.
  write("pos.nc", "G21 G90\nG1 X0 Y0 F100\nG1 X5000 Y0\n");
  EXPECT_EQ(run("tape " + path("pos.nc") + " -o " + path("t.tape") + " --blu 0.000001"), 1);
  EXPECT_EQ(stderr_.rfind(path("pos.nc") + ":3: point (5000, 0) mm is outside the interpolator's position "
                          "range +-2147.48 mm", 0), 0u) << stderr_;
  EXPECT_EQ(files(), std::vector<std::string>{"pos.nc"});
}

TEST_F(TapeCli, LooseTolerancesAndNarrowWidthsWork) {
  // Each of these once stopped with "no chord within the tolerance fits".
  const std::string circle = kExamples + "/circle_r50.json", naca = kExamples + "/naca2412_selig.dat";
  for (const std::string& args : {circle + " --tol 40", naca + " --tol 25", circle + " --width 2",
                                  circle + " --width 3", naca + " --width 3"}) {
    SCOPED_TRACE(args);
    EXPECT_EQ(run("tape " + args + " -o " + path("t.tape")), 0) << stderr_;
    EXPECT_EQ(stderr_, "");
  }
}

TEST_F(TapeCli, SummaryAndReportSayTheDeviationIsSampled) {
  ASSERT_EQ(run("tape " + kExamples + "/circle_r50.json -o " + path("t.tape") + " --tol 10 --report " +
                path("r.json")), 0) << stderr_;
  EXPECT_NE(stdout_.find("max deviation"), std::string::npos) << stdout_;
  EXPECT_NE(stdout_.find("sampled every 2.5 mm"), std::string::npos) << stdout_;
  EXPECT_NE(stdout_.find(" straight, "), std::string::npos) << stdout_;  // every block kind named
  const nlohmann::json r = json_of(path("r.json"));
  EXPECT_EQ(r["deviation"]["step_mm"].get<double>(), 2.5);
  EXPECT_NE(r["deviation"]["measure"].get<std::string>().find("not a bound"), std::string::npos);
}

TEST_F(TapeCli, AirfoilChordMustBePositive) {
  const std::string input = kExamples + "/naca2412_selig.dat";
  for (const char* chord : {"-100", "0"}) {
    EXPECT_EQ(run("tape " + input + " -o " + path("t.tape") + " --airfoil-chord " + chord), 1);
    EXPECT_EQ(stderr_, "ncinterp tape: --airfoil-chord must be > 0 mm (the airfoil's length)\n");
  }
  EXPECT_TRUE(files().empty());
}

TEST_F(TapeCli, UsageErrorsExitOneWithOneLine) {
  const std::string input = kExamples + "/circle_r50.json";
  EXPECT_EQ(run("tape " + input + " -o " + path("t.tape") + " --method 4"), 1);
  EXPECT_EQ(std::count(stderr_.begin(), stderr_.end(), '\n'), 1) << stderr_;
  EXPECT_EQ(run("tape " + input), 1);  // -o is required
  EXPECT_EQ(run("tape " + input + " -o " + path("t.tape") + " --no-such-option"), 1);
  EXPECT_EQ(run("tape " + input + " -o " + path("t.tape") + " --tol abc"), 1);
  EXPECT_EQ(std::count(stderr_.begin(), stderr_.end(), '\n'), 1) << stderr_;
  EXPECT_TRUE(files().empty());
}

}  // namespace
}  // namespace ncinterp::test
