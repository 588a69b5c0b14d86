// `ncinterp play TAPE`: plays a tape through the SystemC system model (tape reader at a
// reader rate, golden or verilated-RTL interpolator, monitors) and reports what the machine
// did: pulses, final position, path error, gaps, feed accuracy (sc_model/system/).
// Outputs: --report (JSON), --vcd (waves, optionally a window --vcd-from/--vcd-to in cycles
// or blocks). Exit 0 when the program played to M02/M30; 1 on a bad tape (one line
// "TAPE: block N, offset K: message"), on unreadable input or unusable options. A bad tape
// still gets its report (complete, status "error": it is the explanation of the failure),
// but never a VCD; every file is written to a temporary and renamed, so nothing is ever
// half-written (docs/waves.md).
#include <chrono>
#include <cmath>
#include <cstdio>
#include <iostream>
#include <optional>

#include "output_set.h"
#include "progress.h"
#include "command_registry.h"
#include "machine_options.h"
#include "play_report.h"
#include "play_run.h"
#include "tape.h"

namespace ncinterp::cli {
namespace {

// A VCD larger than this is announced before it is written.
constexpr uint64_t kLargeVcdBytes = 100'000'000;

struct PlayArgs {
  std::string tape;
  std::string engine = "golden";
  Arch arch = Arch::kSerial;
  double rapid_mm_min = kDefaultRapidMmMin;
  double accel_mm_s2 = 0;
  std::string events;
  std::string vcd, vcd_from, vcd_to, report;
  double clock_hz = 1e6;
  double reader_cps = 1000.0;
  uint64_t max_cycles = 0;
  bool every_clock = false;
};

int run(const PlayArgs& a) {
  using namespace ncinterp::system;
  // Every output reserved before the simulation: a bad --vcd or --report path fails now,
  // not after the whole part has been played.
  OutputSet outputs;
  outputs.input(a.tape);
  AtomicOutputFile* report_out = outputs.add(a.report);
  AtomicOutputFile* vcd_out = outputs.add(a.vcd);
  PlayOptions opt;
  opt.engine = a.engine == "rtl" ? EngineKind::kRtl : EngineKind::kGolden;
  opt.arch = a.arch;
  opt.rapid_mm_min = a.rapid_mm_min;
  opt.accel_mm_s2 = a.accel_mm_s2;
  opt.events = machine_events(a.events, a.clock_hz, a.accel_mm_s2);
  opt.clock_hz = a.clock_hz;
  opt.reader_cps = a.reader_cps;
  opt.vcd_path = a.vcd;
  opt.vcd_file = vcd_out;
  // A whole part at full clock is hundreds of MB: say so before writing it.
  opt.vcd_estimate = [&a](uint64_t bytes, uint64_t cycles) {
    if (bytes < kLargeVcdBytes) return;
    std::fprintf(stderr, "%s: warning: the VCD of about %llu cycles will be about %.0f MB; "
                 "--vcd-from/--vcd-to (cycles or N<block>) write a window\n",
                 a.vcd.c_str(), static_cast<unsigned long long>(cycles), static_cast<double>(bytes) / 1e6);
  };
  opt.max_cycles = a.max_cycles;
  opt.every_clock = a.every_clock;
  if (!a.vcd_from.empty()) opt.vcd_from = parse_vcd_bound(a.vcd_from);
  if (!a.vcd_to.empty()) opt.vcd_to = parse_vcd_bound(a.vcd_to);
  if ((opt.vcd_from || opt.vcd_to) && a.vcd.empty())
    throw std::invalid_argument("--vcd-from/--vcd-to need --vcd");

  const std::vector<uint8_t> frames = tape::load_frames(a.tape);
  // The software reader's view of the tape: the programmed blocks the monitors judge the
  // pulses against (every block before the first error, for a bad tape).
  const tape::ParseResult readback =
      tape::parse_frames_partial(frames, tape_format_of(interp_config(a.clock_hz)));

  Progress progress("play");
  if (progress.enabled())
    opt.progress = [&progress](uint64_t cycle, size_t done, size_t blocks) {
      if (progress.due())
        progress.show("cycle " + std::to_string(cycle) + ", block " + std::to_string(done) + " of " +
                      std::to_string(blocks));
    };
  const PlayResult r = run_play(frames, readback.program, opt);
  progress.clear();
  const nlohmann::json report = play_report(r, a.tape, a.engine, readback.error);
  if (report_out) OutputSet::write(report_out, report.dump(2) + "\n");
  if (vcd_out && !r.vcd_written) outputs.discard(vcd_out);  // a bad tape gets no VCD
  outputs.commit();
  if (!report["reader_agrees"].get<bool>())
    std::cerr << a.tape << ": warning: the software tape reader and the " << a.engine
              << " engine disagree about this tape"
              << (readback.error ? " (reader: " + tape::describe(*readback.error) + ")" : "") << "\n";

  // A run the operator's events ended short of the program's end (a stop, or a pause no
  // cycle start resumes): one line, "TAPE: HEAD at T s, AT X.. Y.. mm TAIL", where the
  // machine stands, and the outputs written.
  const auto ended_short = [&](const std::string& head, const char* at, const char* tail, int status) {
    std::printf("%s: %s at %.6g s%s X%.3f Y%.3f mm%s\n", a.tape.c_str(), head.c_str(),
                report["simulated_seconds"].get<double>(), at,
                static_cast<double>(r.summary.final_x) / std::pow(10.0, r.config.frac_digits),
                static_cast<double>(r.summary.final_y) / std::pow(10.0, r.config.frac_digits), tail);
    if (r.vcd_written) std::printf("VCD: %s\n", a.vcd.c_str());
    if (!a.report.empty()) std::printf("report: %s\n", a.report.c_str());
    return status;
  };
  if (r.stopped())
    return ended_short(std::string(tape_error_message(static_cast<TapeError>(r.summary.error_code))) +
                           " in block N" + std::to_string(r.summary.error_block),
                       ", stopped at", "", kExitStopped);
  if (r.summary.paused)
    return ended_short("paused after block N" +
                           std::to_string(r.summary.timeline.empty() ? 0 : r.summary.timeline.back().n),
                       " (M00, or M01 with the optional stop on), at",
                       "; no cycle start comes (--events start@Ts)", kExitPaused);
  if (const auto e = play_error(r, readback.error)) {
    std::cerr << a.tape << ": block N" << e->block << ", offset " << e->offset << ": "
              << e->message << "\n";
    return 1;
  }
  const PlaySummary& s = r.summary;
  std::printf("%s: %zu blocks, %llu cycles (%.3f s at %g Hz), final position X%.3f Y%.3f mm, "
              "max path error %.3f BLU\n",
              a.tape.c_str(), s.blocks_played, static_cast<unsigned long long>(s.cycles),
              report["simulated_seconds"].get<double>(), a.clock_hz,
              static_cast<double>(s.final_x) / std::pow(10.0, r.config.frac_digits),
              static_cast<double>(s.final_y) / std::pow(10.0, r.config.frac_digits),
              s.max_path_error);
  if (r.vcd_written) std::printf("VCD: %s\n", a.vcd.c_str());
  if (!a.report.empty()) std::printf("report: %s\n", a.report.c_str());
  return 0;
}

void setup(CLI::App& app) {
  auto args = std::make_shared<PlayArgs>();
  CLI::App* cmd = app.add_subcommand("play", "Play a tape through the SystemC system model");
  cmd->add_option("tape", args->tape, "Tape: .tape (frames with parity) or plain text (.nc)")
      ->required();
  cmd->add_option("--engine", args->engine, "Interpolator: golden (C++ model) or rtl (verilated)")
      ->check(CLI::IsMember({"golden", "rtl"}))
      ->capture_default_str();
  add_arch_option(cmd, args->arch);
  add_rapid_option(cmd, args->rapid_mm_min);
  add_accel_option(cmd, args->accel_mm_s2);
  add_events_option(cmd, args->events);
  cmd->add_option("--vcd", args->vcd, "Write waves (VCD) to this file");
  const auto bound_check = [](const std::string& s) -> std::string {
    try {
      ncinterp::system::parse_vcd_bound(s);
      return {};
    } catch (const std::exception& e) {
      return e.what();
    }
  };
  cmd->add_option("--vcd-from", args->vcd_from, "VCD starts at this cycle (1000) or block (N12)")
      ->check(bound_check);
  cmd->add_option("--vcd-to", args->vcd_to, "VCD ends at this cycle (5000) or block's end (N12)")
      ->check(bound_check);
  cmd->add_option("--report", args->report, "Write the JSON report to this file");
  cmd->add_option("--clock-hz", args->clock_hz, "Interpolator clock, Hz")->capture_default_str();
  cmd->add_option("--reader-cps", args->reader_cps, "Tape reader speed, characters per second")
      ->capture_default_str();
  cmd->add_flag("--every-clock", args->every_clock,
                "golden engine: tick every clock instead of passing the clocks where only the feed "
                "phase and the reader's wait advance in one step (the same report, slower)");
  cmd->add_option("--max-cycles", args->max_cycles,
                  "Stop (as an error) after this many cycles; 0 = a bound from the tape")
      ->capture_default_str();
  cmd->callback([args] { run_command("play", [&] { return run(*args); }); });
}

const CommandRegistration registration("play", setup);

}  // namespace
}  // namespace ncinterp::cli
