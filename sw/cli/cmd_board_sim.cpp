// `ncinterp board-sim --board icestick --pty PATH [--report R.json] [--vcd W.vcd]`: the
// virtual board (sc_model/board/board_sim.h): the verilated board core, UART included, in
// simulated time at the board's clock, behind a pseudo-terminal linked at PATH, so
// `ncinterp send TAPE --port PATH` (or any serial program) talks to it.
// Ends when the board reports the program done or an error (or the sender stays silent
// longer than --idle-timeout): writes the report (play's JSON fields plus "board") and, for
// a run that played to its end, the VCD; exit 0 when the program played to its end, 5 when
// an E-stop or a limit of --events stopped it, 6 when it paused with no cycle start to
// come (as play), 1 otherwise (with the board's error on stderr).
// --events drives the board's operator pins (board_sim.h).
#include <cstdio>
#include <iostream>

#include "atomic_file.h"
#include "board_sim.h"
#include "boards.h"
#include "command_registry.h"
#include "machine_options.h"

namespace ncinterp::cli {
namespace {

struct BoardSimArgs {
  board::BoardSimOptions options;
  std::string flow;
  std::string report;
  std::string events;
};

int run(BoardSimArgs& a) {
  board::BoardSimOptions& o = a.options;
  if (a.flow.empty()) a.flow = board::board_named(o.board).flow;
  o.flow = board::flow_named(a.flow);
  if (o.flow == board::Flow::kCount && !board::board_named(o.board).operator_pins)
    throw std::invalid_argument("--flow count: the " + o.board + "'s core sends no ACKs (docs/board.md)");
  o.events = parse_events(a.events, o.clock_hz);
  const board::BoardSimResult r = board::run_board_sim(o, [&](const std::string& path) {
    std::printf("board-sim: %s on %s (%g Hz, %u baud, %s)\n", o.board.c_str(), path.c_str(), o.clock_hz,
                o.baud, a.flow.c_str());
    std::fflush(stdout);
  });
  const nlohmann::json report = board::board_sim_report(r, o);
  if (!a.report.empty()) write_file_atomically(a.report, report.dump(2) + "\n");
  // A B line goes out every line time while the machine moves: the count and the last.
  if (!r.status_lines.empty())
    std::printf("board: %zu status lines, the last \"%s\"\n", r.status_lines.size(),
                r.status_lines.back().c_str());
  const system::PlaySummary& s = r.play.summary;
  if (r.play.stopped() || s.paused) {
    std::printf("board-sim: %s in block N%u, at X%lld Y%lld BLU\n", r.play.stopped() ? "stopped" : "paused",
                r.play.stopped() ? s.error_block : s.timeline.empty() ? 0u : s.timeline.back().n,
                static_cast<long long>(s.final_x), static_cast<long long>(s.final_y));
    return r.play.stopped() ? kExitStopped : kExitPaused;
  }
  if (report["status"] != "ok") {
    std::cerr << "board-sim: "
              << (report.contains("error") ? report["error"].value("message", std::string("error"))
                  : r.timed_out          ? "the sender stayed silent before the end of the program"
                                         : "the program did not end")
              << "\n";
    return 1;
  }
  std::printf("board-sim: %zu blocks, %llu cycles, final position X%lld Y%lld BLU\n",
              r.play.summary.blocks_played, static_cast<unsigned long long>(r.play.summary.cycles),
              static_cast<long long>(r.play.summary.final_x), static_cast<long long>(r.play.summary.final_y));
  return 0;
}

void setup(CLI::App& app) {
  auto args = std::make_shared<BoardSimArgs>();
  board::BoardSimOptions& o = args->options;
  CLI::App* cmd = app.add_subcommand("board-sim", "Run the virtual board behind a pseudo-terminal");
  cmd->add_option("--board", o.board, "Board: icestick or icebreaker")
      ->check(CLI::IsMember({"icestick", "icebreaker"}))
      ->capture_default_str();
  cmd->add_option("--pty", o.pty_link, "Path of the symlink to the pty (the port for `send`)")->required();
  cmd->add_option("--report", args->report, "Write the JSON report to this file");
  cmd->add_option("--vcd", o.vcd_path, "Write the board core's waves (VCD) to this file");
  cmd->add_option("--clock-hz", o.clock_hz, "Board clock, Hz (the boards: 12e6)")->capture_default_str();
  cmd->add_option("--baud", o.baud, "UART baud rate")->capture_default_str();
  cmd->add_option("--accel", o.accel_mm_s2,
                  "The feed ramp's acceleration limit, mm/s^2 (default: the board's, 500 on the "
                  "iCEBreaker; 0: no ramp; the iCEstick's core has none)")
      ->check(CLI::NonNegativeNumber);
  add_rapid_option(cmd, o.rapid_mm_min);
  add_events_option(cmd, args->events);
  cmd->add_option("--flow", args->flow,
                  "Flow control: rtscts or xonxoff (the USB-serial chip honours the board's), or count "
                  "(none in the chip: the sender counts the board's ACKs) (default: rtscts on the "
                  "iCEstick, count on the iCEBreaker)")
      ->check(CLI::IsMember({"rtscts", "xonxoff", "count"}));
  cmd->add_option("--max-cycles", o.max_cycles, "Stop after this many clocks (0: no limit)")->capture_default_str();
  cmd->add_option("--idle-timeout", o.idle_timeout_s, "Give up after this long without a byte, wall s")
      ->capture_default_str();
  cmd->callback([args] { run_command("board-sim", [&] { return run(*args); }); });
}

const CommandRegistration registration("board-sim", setup);

}  // namespace
}  // namespace ncinterp::cli
