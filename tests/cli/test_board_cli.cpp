// The virtual board end to end, through a real pseudo-terminal: `ncinterp board-sim`
// (verilated board core, UART included) fed by `ncinterp send`, against `ncinterp play` on
// the same tape: the same pulses and final position on the bundled examples (lines and
// arcs); a flipped parity bit makes send fail naming the block, with no pulse from that
// block; flow control engaged (RTS/CTS, XON/XOFF, character counting) with no frame lost,
// also on blocks too short for the line to keep ahead; the operator's keys, sent by send as
// realtime bytes, hold, resume, override and stop the iCEBreaker.
// The board runs at 1 MHz and 115200 baud (9 clocks per bit) instead of 12 MHz: the same
// RTL and the same clock/baud relation, an eighth of the clocks to simulate (CI time).
#include <fcntl.h>
#include <spawn.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <thread>

#include "cli_test.h"
#include "tape.h"

extern char** environ;

namespace fs = std::filesystem;

namespace {

const std::string kExamples = NCINTERP_EXAMPLES_DIR;
const char* const kClock = "1e6";

class BoardCli : public ncinterp::test::CliTest {
 protected:
  // Starts board-sim in the background on path("tty"), waits for its pty link.
  void start_board(const std::string& args) {
    const std::string cmd = std::string(NCINTERP_BINARY) + " board-sim --pty " + path("tty") +
                            " --clock-hz " + kClock + " --idle-timeout 60 --report " + path("board.json") + " " +
                            args + " >" + path("board.out") + " 2>" + path("board.err");
    const char* argv[] = {"/bin/sh", "-c", cmd.c_str(), nullptr};
    ASSERT_EQ(posix_spawn(&board_pid_, "/bin/sh", nullptr, nullptr, const_cast<char**>(argv), environ), 0);
    for (int i = 0; i < 300 && !fs::is_symlink(path("tty")); ++i)
      std::this_thread::sleep_for(std::chrono::milliseconds(50));
    ASSERT_TRUE(fs::is_symlink(path("tty"))) << slurp(path("board.err"));
  }
  // Waits for board-sim; returns its exit status and its report.
  int finish_board() {
    int status = 0;
    waitpid(board_pid_, &status, 0);
    board_pid_ = 0;
    board_err_ = slurp(path("board.err"));
    if (fs::exists(path("board.json"))) board_ = nlohmann::json::parse(slurp(path("board.json")));
    return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  }
  void TearDown() override {
    if (board_pid_) {
      kill(board_pid_, SIGTERM);
      waitpid(board_pid_, nullptr, 0);
    }
    CliTest::TearDown();
  }
  nlohmann::json play(const std::string& tape) {
    EXPECT_EQ(run("play " + tape + " --clock-hz " + kClock + " --report " + path("play.json")), 0) << stderr_;
    return nlohmann::json::parse(slurp(path("play.json")));
  }
  // The tape through send -> board-sim; returns send's exit status.
  int send_to_board(const std::string& tape, const std::string& board_args, const std::string& send_args) {
    start_board(board_args);
    const int code = run("send " + tape + " --port " + path("tty") + " --timeout 60 " + send_args);
    send_out_ = stdout_;
    send_err_ = stderr_;
    board_code_ = finish_board();
    return code;
  }
  void expect_same_motion(const nlohmann::json& p) {
    EXPECT_EQ(board_["pulses"], p["pulses"]);
    EXPECT_EQ(board_["final_position_blu"], p["final_position_blu"]);
    EXPECT_EQ(board_["blocks"], p["blocks"]);
    EXPECT_EQ(board_["status"], p["status"]);
    EXPECT_EQ(board_["path_within_bound"], p["path_within_bound"]);
  }

  // line.nc: one 20 mm line that lasts a second (F60, inverse time).
  void write_line_tape() {
    std::ofstream(path("line.nc")) << "%\nG17 G21 G91 G93\nN1 G01 X20.000 Y5.000 F60.000\nM02\n%\n";
  }

  pid_t board_pid_ = 0;
  int board_code_ = -1;
  nlohmann::json board_;
  std::string board_err_, send_out_, send_err_;
};

TEST_F(BoardCli, GearLinesThroughThePtyMatchPlay) {
  const std::string tape = kExamples + "/gear.nc";
  const nlohmann::json p = play(tape);
  ASSERT_EQ(send_to_board(tape, "--board icestick", "--flow rtscts"), 0) << send_err_ << board_err_;
  ASSERT_EQ(board_code_, 0) << board_err_;
  expect_same_motion(p);
  EXPECT_EQ(board_["frames_read"], p["frames"]);  // no frame lost
  EXPECT_EQ(board_["board"]["board_error"], 0);
  // The line is faster than the gear's blocks play: the FIFO filled and CTS# held the
  // sender back.
  EXPECT_GT(board_["board"]["flow_hold_cycles"].get<uint64_t>(), 0u);
  EXPECT_NE(send_out_.find("program done after block N48"), std::string::npos) << send_out_;
  EXPECT_NE(send_out_.find("block N1 playing"), std::string::npos) << send_out_;
}

// Arcs play on the iCEBreaker, whose core has circle mode.
TEST_F(BoardCli, CircleArcsThroughThePtyMatchPlay) {
  const std::string tape = kExamples + "/circle_r50.nc";
  const nlohmann::json p = play(tape);
  ASSERT_EQ(send_to_board(tape, "--board icebreaker", "--flow count"), 0) << send_err_ << board_err_;
  ASSERT_EQ(board_code_, 0) << board_err_;
  expect_same_motion(p);
  EXPECT_EQ(board_["frames_read"], p["frames"]);
  EXPECT_EQ(board_["final_position_blu"]["x"], 0);
}

// The iCEstick's core is built without circle mode: an arc tape stops at its first arc
// block with the named error and no pulse from it; `tape --board icestick` refuses to
// write one, saying why.
TEST_F(BoardCli, ArcsOnTheLinesOnlyIcestickStopWithTheirOwnError) {
  const std::string tape = kExamples + "/circle_r50.nc";
  EXPECT_EQ(send_to_board(tape, "--board icestick", ""), 1);
  EXPECT_NE(send_err_.find("without circle mode"), std::string::npos) << send_err_;
  EXPECT_EQ(board_code_, 1);
  EXPECT_EQ(board_["status"], "error");
  EXPECT_EQ(board_["error"]["code"], 13);
  EXPECT_EQ(board_["blocks"], 0);
  EXPECT_EQ(run("tape " + kExamples + "/contours/circle_r50.json -o " + path("c.tape") +
                " --arcs circle --board icestick"), 1);
  EXPECT_NE(stderr_.find("--board icestick: its interpolator is built without circle mode"),
            std::string::npos) << stderr_;
  EXPECT_FALSE(fs::exists(path("c.tape")));
}

// XON/XOFF, and character counting, the iCEBreaker's flow control: with counting its chip
// holds nothing back, send keeps at most the board's FIFO (256 bytes) unacknowledged, and
// the board ACKs every 32 bytes it takes. The gear's 48 blocks fill the FIFO and no frame is
// lost either way; a sender that does not count (a plain write loop) overflows it, and the
// board stops with its own error.
TEST_F(BoardCli, XonXoffAndCharacterCountingLoseNoFrame) {
  const std::string tape = kExamples + "/gear.nc";
  const nlohmann::json p = play(tape);
  for (const std::string flow : {"xonxoff", "count"}) {
    ASSERT_EQ(send_to_board(tape, "--board icebreaker --flow " + flow, "--no-keys --flow " + flow), 0)
        << send_err_ << board_err_;
    ASSERT_EQ(board_code_, 0) << board_err_;
    expect_same_motion(p);
    EXPECT_EQ(board_["board"]["flow"], flow);
    EXPECT_EQ(board_["frames_read"], p["frames"]);
    EXPECT_GT(board_["board"]["max_fifo_level"].get<unsigned>(), 100u) << flow;
    if (flow == "xonxoff") EXPECT_GT(board_["board"]["xoff_sent"].get<uint64_t>(), 0u);
  }
  EXPECT_LE(board_["board"]["max_fifo_level"].get<unsigned>(), 256u);
  const unsigned taken = p["frames"].get<unsigned>() + 1;  // and the EOT frame
  EXPECT_GE(board_["board"]["acks_sent"].get<unsigned>() + 1, taken / 32);
  EXPECT_LE(board_["board"]["acks_sent"].get<unsigned>(), taken / 32);
  EXPECT_GT(board_["board"]["max_fifo_level"].get<unsigned>(), 200u);

  EXPECT_EQ(send_to_board(tape, "--board icebreaker", "--flow rtscts"), 1);
  EXPECT_EQ(board_["board"]["board_error"], 0x20) << board_err_;
  EXPECT_NE(send_err_.find("FIFO overflowed"), std::string::npos) << send_err_;
}

// The operator's keys through send (--keys, here from a pipe). A hold typed at once holds
// the machine near its start for good when no cycle start follows (board-sim ends at half
// play's clocks, when the machine would be halfway without the hold). A hold and two feed override steps, with a cycle start half a second
// later: the board takes each as one realtime command, the held machine waits for the start
// (with its FIFO full, the pair of bytes still gets through), and the program ends where
// play's ends, with the same pulses. An E-stop key stops the line: send and board-sim exit
// 5, the board's error line names the stop.
TEST_F(BoardCli, SendsKeysThatHoldResumeOverrideAndStopTheIcebreaker) {
  const std::string tape = kExamples + "/gear.nc";
  const nlohmann::json p = play(tape);
  const auto send_with_keys = [&](const std::string& first, const std::string& later,
                                  const std::string& board_args = "") {
    const std::string keys = path("keys");
    EXPECT_EQ(mkfifo(keys.c_str(), 0600), 0);
    std::thread typist([&] {
      std::ofstream k(keys);  // opens when send's shell opens the other end
      k << first << std::flush;
      std::this_thread::sleep_for(std::chrono::milliseconds(500));
      k << later << std::flush;
    });
    start_board("--board icebreaker " + board_args);
    const int code = run("send " + tape + " --port " + path("tty") + " --timeout 60 --flow count --keys < " + keys);
    typist.join();
    fs::remove(keys);
    send_out_ = stdout_;
    send_err_ = stderr_;
    board_code_ = finish_board();
    return code;
  };
  const uint64_t play_cycles = p["cycles"];
  EXPECT_EQ(send_with_keys("h", "", "--max-cycles " + std::to_string(play_cycles / 2)), 4) << send_err_;
  EXPECT_EQ(board_["board"]["realtime_commands"]["Hold"], 1);
  EXPECT_NE(board_["status"], "ok");
  const int64_t moved = board_["pulses"]["x"]["plus"].get<int64_t>() + board_["pulses"]["x"]["minus"].get<int64_t>();
  EXPECT_LT(moved, p["pulses"]["x"]["plus"].get<int64_t>() / 10) << "the hold did not hold";

  ASSERT_EQ(send_with_keys("h++", "s"), 0) << send_err_ << board_err_;
  ASSERT_EQ(board_code_, 0) << board_err_;
  expect_same_motion(p);
  const nlohmann::json& taken = board_["board"]["realtime_commands"];
  EXPECT_EQ(taken["Hold"], 1);
  EXPECT_EQ(taken["FeedUp"], 2);
  EXPECT_EQ(taken["Start"], 1) << "the program ended before the cycle start: the hold did not hold";
  EXPECT_EQ(taken["EStop"], 0);
  EXPECT_EQ(board_["board"]["board_error"], 0);

  EXPECT_EQ(send_with_keys("", "x"), 5) << send_err_;
  EXPECT_EQ(board_code_, 5) << board_err_;
  EXPECT_EQ(board_["status"], "stopped");
  EXPECT_EQ(board_["error"]["code"], 14);
  EXPECT_NE(send_err_.find("emergency stop"), std::string::npos) << send_err_;
}

// A realtime byte without its twin (what a line error makes of a frame) is not a command
// and not lost: the board stops with its own error. Keys need a board that counts.
TEST_F(BoardCli, ALoneRealtimeByteStopsTheBoardWithItsOwnError) {
  start_board("--board icebreaker");
  const int port = open(path("tty").c_str(), O_RDWR | O_NOCTTY);
  ASSERT_GE(port, 0);
  const char bytes[] = {'h', '\xa5'};  // hold, then the tape's '%' (ISO 840 parity)
  ASSERT_EQ(::write(port, bytes, sizeof bytes), 2);
  close(port);
  EXPECT_EQ(finish_board(), 1);
  EXPECT_EQ(board_["board"]["board_error"], 0x23);
  EXPECT_NE(board_err_.find("without its twin"), std::string::npos) << board_err_;
  EXPECT_EQ(run("send " + kExamples + "/gear.nc --port " + path("tty") + " --keys"), 1);
  EXPECT_NE(stderr_.find("--keys: realtime commands need --flow count"), std::string::npos) << stderr_;
}

// The iCEBreaker's core ramps at 500 mm/s^2 (its bitstream's AccelMmS2): a line of 2^15
// iterations at F60 has the rate S = 60000 * 2^15, which the ramp reaches in S / du =
// 65 536 clocks at du = 30 000 (1 MHz): its trapezoid makes the block that much longer
// than without the ramp, a little less with the ramp's discrete steps, with the same
// pulses. The iCEstick's core has no ramp and says so.
TEST_F(BoardCli, TheIcebreakerRampsEveryBlockWithTheSamePulses) {
  write_line_tape();
  const nlohmann::json p = play(path("line.nc"));
  ASSERT_EQ(send_to_board(path("line.nc"), "--board icebreaker --accel 0", ""), 0) << send_err_ << board_err_;
  const nlohmann::json unramped = board_;
  ASSERT_EQ(send_to_board(path("line.nc"), "--board icebreaker", ""), 0) << send_err_ << board_err_;
  ASSERT_EQ(board_code_, 0) << board_err_;
  expect_same_motion(p);
  EXPECT_EQ(board_["accel_mm_s2"], 500);
  EXPECT_EQ(unramped["pulses"], board_["pulses"]);
  const double longer_s = (board_["cycles"].get<double>() - unramped["cycles"].get<double>()) / 1e6;
  EXPECT_GT(longer_s, 0.060);
  EXPECT_LE(longer_s, 0.065536);
  EXPECT_EQ(run("board-sim --board icestick --accel 100 --pty " + path("tty2")), 1);
  EXPECT_NE(stderr_.find("the icestick's core is built without the feed ramp"), std::string::npos) << stderr_;
  EXPECT_FALSE(fs::exists(path("tty2")));
}

// The iCEBreaker's operator pins, pressed by board-sim --events: a feed hold and a
// resume (buttons, debounced) keep the pulses and make the run that much longer; an
// E-stop (a switch) stops the line with status "stopped" and exit 5, its position its
// pulses. The iCEstick's core has no such pins and says so.
TEST_F(BoardCli, TheIcebreakersPinsHoldResumeAndStop) {
  write_line_tape();
  const nlohmann::json p = play(path("line.nc"));
  ASSERT_EQ(send_to_board(path("line.nc"), "--board icebreaker", ""), 0) << send_err_ << board_err_;
  const nlohmann::json unheld = board_;
  ASSERT_EQ(send_to_board(path("line.nc"), "--board icebreaker --events hold@0.3s,resume@0.7s", ""), 0)
      << send_err_ << board_err_;
  ASSERT_EQ(board_code_, 0) << board_err_;
  expect_same_motion(p);
  // The run is as much longer as the machine was held from press to resume: the brake
  // and the climb again each take S / du and cover half that time's cruise. That is 0.4 s
  // give or take a debounce sample period (each press is seen 1 to 2 periods of 65.5 ms
  // late at 1 MHz).
  const double longer_s = (board_["cycles"].get<double>() - unheld["cycles"].get<double>()) / 1e6;
  EXPECT_GT(longer_s, 0.4 - 0.066);
  EXPECT_LT(longer_s, 0.4 + 0.066);

  EXPECT_NE(send_to_board(path("line.nc"), "--board icebreaker --events estop@0.5s", ""), 0);
  EXPECT_EQ(board_code_, 5) << board_err_;
  EXPECT_EQ(board_["status"], "stopped");
  EXPECT_EQ(board_["error"]["code"], 14);
  const int64_t x = board_["final_position_blu"]["x"];
  EXPECT_GT(x, 5000);
  EXPECT_LT(x, 15000);
  EXPECT_EQ(x, board_["pulses"]["x"]["plus"].get<int64_t>());

  EXPECT_EQ(run("board-sim --board icestick --events hold@1s --pty " + path("tty2")), 1);
  EXPECT_NE(stderr_.find("the icestick's core is built without the operator's pins"), std::string::npos)
      << stderr_;
  EXPECT_EQ(run("board-sim --board icebreaker --events override=55@1s --pty " + path("tty2")), 1);
  EXPECT_NE(stderr_.find("an override of 54.7 % is none of their steps"), std::string::npos) << stderr_;
  EXPECT_FALSE(fs::exists(path("tty2")));
}

// The override buttons, pressed by board-sim --events: two presses of -10 % slow a slow
// line (20 mm at 5 mm/s) to 80 %, and a press of 100 % later brings it back; the pulses
// are play's, and the run takes longer than without the presses, less long with the
// return to 100 %.
TEST_F(BoardCli, TheIcebreakersOverrideButtonsScaleTheFeed) {
  { std::ofstream(path("slow.nc")) << "%\nG17 G21 G91 G93\nN1 G01 X20.000 Y5.000 F15.000\nM02\n%\n"; }
  const nlohmann::json p = play(path("slow.nc"));
  ASSERT_EQ(send_to_board(path("slow.nc"), "--board icebreaker", ""), 0) << send_err_ << board_err_;
  const double plain = board_["cycles"];
  ASSERT_EQ(send_to_board(path("slow.nc"), "--board icebreaker --events override=80@0.2s", ""), 0) << board_err_;
  expect_same_motion(p);
  const double slowed = board_["cycles"];
  ASSERT_EQ(send_to_board(path("slow.nc"), "--board icebreaker --events override=80@0.2s,override=100@2s", ""), 0)
      << board_err_;
  expect_same_motion(p);
  const double back = board_["cycles"];
  // At 80 % from about 0.7 s (two presses) on: about a quarter longer for the rest of the 4 s.
  EXPECT_GT(slowed, plain + 0.6e6);
  EXPECT_LT(back, slowed - 0.2e6);
  EXPECT_GT(back, plain + 0.2e6);
}

// On the iCEBreaker an M00 waits for the cycle start button: with no press to come the
// run ends there (exit 6, status "paused"), with one it plays to its end.
TEST_F(BoardCli, TheIcebreakersPauseWaitsForItsCycleStartButton) {
  std::ofstream(path("m.nc")) << "%\nG17 G21 G91 G93\nN1 G01 X2.000 Y1.000 F600.000 M03\nN2 M00\n"
                                 "N3 G01 X-1.000 Y2.000 F600.000 M05\nM02\n%\n";
  EXPECT_NE(send_to_board(path("m.nc"), "--board icebreaker", ""), 0);
  EXPECT_EQ(board_code_, 6) << board_err_;
  EXPECT_EQ(board_["status"], "paused");
  EXPECT_EQ(board_["final_position_blu"]["x"], 2000);
  ASSERT_EQ(send_to_board(path("m.nc"), "--board icebreaker --events start@0.5s", ""), 0) << send_err_ << board_err_;
  EXPECT_EQ(board_code_, 0) << board_err_;
  EXPECT_EQ(board_["final_position_blu"]["x"], 1000);
  EXPECT_EQ(board_["final_position_blu"]["y"], 3000);
  EXPECT_GT(board_["paused_cycles"].get<uint64_t>(), 300000u);
}

TEST_F(BoardCli, ShortBlocksTheLineCannotKeepAheadOfLoseNoFrame) {
  // 300 one-step blocks at a high feed: each plays in far less time than its ~30 frames
  // take on the line, so the interpolator waits for the reader (gaps), never the reverse.
  std::string text = "%\nG17 G21 G91 G93\n";
  for (int n = 1; n <= 300; ++n)
    text += "N" + std::to_string(n) + " G01 X" + (n % 2 ? "0.001" : "-0.002") + " Y0.001 F60000.000\n";
  text += "M02\n%\n";
  { std::ofstream(path("short.nc")) << text; }
  const nlohmann::json p = play(path("short.nc"));
  ASSERT_EQ(send_to_board(path("short.nc"), "--board icestick", ""), 0) << send_err_ << board_err_;
  ASSERT_EQ(board_code_, 0) << board_err_;
  expect_same_motion(p);
  EXPECT_EQ(board_["blocks"], 300);
  EXPECT_EQ(board_["frames_read"], p["frames"]);
  EXPECT_GT(board_["gap_cycles"].get<uint64_t>(), 0u);  // the line could not keep ahead
  EXPECT_EQ(board_["board"]["board_error"], 0);
}

TEST_F(BoardCli, FlippedParityFailsNamingTheBlockWithNoPulseFromIt) {
  std::vector<uint8_t> frames = ncinterp::tape::load_frames(kExamples + "/gear.nc");
  // A digit of block N5's X word with its parity bit flipped.
  std::string plain;
  for (const uint8_t f : frames) plain += static_cast<char>(f & 0x7f);
  const size_t word = plain.find("N5 G01 X");
  ASSERT_NE(word, std::string::npos);
  const size_t at = word + 9;
  frames[at] ^= 0x80;
  {
    std::ofstream out(path("bad.tape"), std::ios::binary);
    out.write(reinterpret_cast<const char*>(frames.data()), static_cast<std::streamsize>(frames.size()));
  }
  EXPECT_EQ(run("play " + path("bad.tape") + " --clock-hz " + kClock + " --report " + path("play.json")), 1);
  const nlohmann::json p = nlohmann::json::parse(slurp(path("play.json")));
  EXPECT_EQ(send_to_board(path("bad.tape"), "--board icestick", ""), 1);
  EXPECT_NE(send_err_.find("block N5, offset " + std::to_string(at)), std::string::npos) << send_err_;
  EXPECT_EQ(board_code_, 1);
  EXPECT_EQ(board_["status"], "error");
  EXPECT_EQ(board_["error"]["block"], 5);
  // Blocks N1..N4 played, nothing of N5: the board stopped where the programmed N1..N4 end.
  EXPECT_EQ(board_["blocks"], 4);
  EXPECT_EQ(board_["final_position_blu"], board_["expected_position_blu"]);
  EXPECT_EQ(board_["pulses_beyond_program"], 0);
  expect_same_motion(p);
}

TEST_F(BoardCli, SendAndBoardSimRefuseUnusableOptionsClearly) {
  { std::ofstream(path("plain.txt")) << "not a port"; }
  EXPECT_EQ(run("send " + kExamples + "/gear.nc --port " + path("plain.txt")), 1);
  EXPECT_NE(stderr_.find("not a serial port"), std::string::npos) << stderr_;
  EXPECT_EQ(run("send " + kExamples + "/gear.nc --port " + path("tty") + " --baud 12345"), 1);
  EXPECT_NE(stderr_.find("not a standard termios rate"), std::string::npos) << stderr_;
  // 1 MHz / 921600 baud is about one clock per bit: the board's receiver needs 4.
  EXPECT_EQ(run("board-sim --pty " + path("tty") + " --clock-hz 1e6 --baud 921600"), 1);
  EXPECT_NE(stderr_.find("the board needs 4 to 4095"), std::string::npos) << stderr_;
  EXPECT_FALSE(fs::exists(path("tty")));
}

// A port that takes the tape and never answers (the board is off, or a wrong device): send
// gives up after --timeout with exit 4 (the board failed), not 1 (a bad tape), and says how
// far it got.
TEST_F(BoardCli, SendToASilentPortExitsFourAfterTheTimeout) {
  const int master = posix_openpt(O_RDWR | O_NOCTTY);
  ASSERT_GE(master, 0);
  ASSERT_EQ(grantpt(master), 0);
  ASSERT_EQ(unlockpt(master), 0);
  const std::string port = ptsname(master);
  const auto start = std::chrono::steady_clock::now();
  EXPECT_EQ(run("send " + kExamples + "/gear.nc --port " + port + " --timeout 0.5"), 4) << stderr_;
  EXPECT_LT(std::chrono::steady_clock::now() - start, std::chrono::seconds(20));
  EXPECT_NE(stderr_.find("nothing moved for 0.5 s"), std::string::npos) << stderr_;
  EXPECT_EQ(stderr_.find('\n'), stderr_.size() - 1) << "more than one line: " << stderr_;
  close(master);
  EXPECT_EQ(run("send " + kExamples + "/gear.nc --port " + port + " --timeout -1"), 1);
}

// bitstream checks its output before any tool runs: a directory as -o fails at once, and no
// work directory is made for it.
TEST_F(BoardCli, BitstreamRefusesAnUnwritableOutputBeforeTheTools) {
  fs::create_directory(path("out.bin"));
  const auto start = std::chrono::steady_clock::now();
  EXPECT_EQ(run("bitstream --board icestick -o " + path("out.bin")), 1);
  EXPECT_LT(std::chrono::steady_clock::now() - start, std::chrono::seconds(5));
  EXPECT_NE(stderr_.find(path("out.bin")), std::string::npos) << stderr_;
  EXPECT_FALSE(fs::exists(path("out.bin.build")));
}

}  // namespace
