// `ncinterp cosim TAPE`: the verilated RTL and the golden model play the same tape in lock
// step (each fed by its own tape reader model) and every output is compared after every
// clock (sc_model/cosim/). On the first mismatch: one line with the cycle, block N, signal,
// expected (golden) and actual (RTL) values and the cycles matched before it, exit 2, and
// with --vcd a VCD of the RTL around it (a re-run of the trace-enabled RTL).
// Exit codes: 0 the engines agreed on every clock up to done; 1 bad input (unreadable tape,
// bad options) or a bad tape (both engines agree on the error: "TAPE: block N, offset K:
// message"); 2 mismatch; 3 cycle limit reached. --report (JSON) is written in every case
// the cosim ran (it explains the failure); every file is written to a temporary and renamed.

#include <chrono>
#include <cstdio>
#include <iostream>
#include <memory>
#include <nlohmann/json.hpp>
#include <sstream>
#include <stdexcept>

#include "output_set.h"
#include "progress.h"
#include "command_registry.h"
#include "machine_options.h"
#include "frame_source.h"
#include "lockstep.h"
#include "play_run.h"
#include "rtl_vcd.h"
#include "tape.h"

namespace ncinterp::cli {
namespace {

struct CosimArgs {
  std::string tape;
  Arch arch = Arch::kSerial;
  double rapid_mm_min = kDefaultRapidMmMin;
  double accel_mm_s2 = 0;
  std::string events;
  std::string report, vcd;
  double clock_hz = 1e6;
  double reader_cps = 1000.0;
  uint64_t max_cycles = 0;
  uint64_t vcd_window = 1000;
  std::string fault;
};

// "lost-pulse:CYCLE:AXIS" etc. -> a golden-model fault (test hook for the scoreboard).
GoldenInterp::Fault parse_fault(const std::string& text) {
  std::istringstream in(text);
  std::string kind, cycle, axis;
  std::getline(in, kind, ':');
  std::getline(in, cycle, ':');
  std::getline(in, axis);
  GoldenInterp::Fault f;
  if (kind == "lost-pulse") f.kind = GoldenInterp::Fault::kLostPulse;
  else if (kind == "stuck-step") f.kind = GoldenInterp::Fault::kStuckStep;
  else if (kind == "accumulator") f.kind = GoldenInterp::Fault::kAccumulatorOffByOne;
  else if (kind == "wrong-direction") f.kind = GoldenInterp::Fault::kWrongDirection;
  else throw std::invalid_argument("--inject-fault: unknown kind '" + kind + "'");
  if (axis != "x" && axis != "y") throw std::invalid_argument("--inject-fault: axis must be x or y");
  try {
    f.cycle = std::stoull(cycle);
  } catch (const std::exception&) {
    throw std::invalid_argument("--inject-fault: bad cycle '" + cycle + "'");
  }
  f.axis = axis == "x" ? 0 : 1;
  return f;
}

const char* end_name(cosim::Result::End end) {
  switch (end) {
    case cosim::Result::End::kDone: return "done";
    case cosim::Result::End::kTapeError: return "error";
    case cosim::Result::End::kMismatch: return "mismatch";
    case cosim::Result::End::kCycleLimit: return "cycle_limit";
    case cosim::Result::End::kPaused: return "paused";
  }
  return "?";
}

nlohmann::json report_json(const CosimArgs& a, const cosim::Options& o, const cosim::Result& r,
                           double seconds, const std::string& vcd_written,
                           uint64_t vcd_from, uint64_t vcd_to) {
  nlohmann::json j;
  j["tape"] = a.tape;
  j["arch"] = arch_name(o.config.arch);
  j["accel_mm_s2"] = a.accel_mm_s2;
  j["clock_hz"] = a.clock_hz;
  j["reader_cps"] = a.reader_cps;
  j["cycles_per_frame"] = o.cycles_per_frame;
  j["cycle_limit"] = o.max_cycles;
  j["status"] = r.mismatch ? "mismatch" : (r.end == cosim::Result::End::kCycleLimit ? "cycle_limit" : "match");
  j["end"] = r.end == cosim::Result::End::kTapeError && is_stop_error(r.last.error_code) ? "stopped"
                                                                                        : end_name(r.end);
  j["cycles"] = r.cycles;
  j["blocks"] = r.stats.blocks;
  j["saturated_blocks"] = r.stats.saturated_blocks;
  j["gap_cycles"] = r.stats.gap_cycles;
  j["pulses"] = {{"x", {{"plus", r.stats.pulses[0][1]}, {"minus", r.stats.pulses[0][0]}}},
                 {"y", {{"plus", r.stats.pulses[1][1]}, {"minus", r.stats.pulses[1][0]}}}};
  j["final_position_blu"] = {{"x", r.last.pos_x}, {"y", r.last.pos_y}};
  if (r.mismatch) {
    const cosim::Mismatch& m = *r.mismatch;
    j["mismatch"] = {{"cycle", m.cycle},       {"block", m.block},
                     {"signal", m.signal},     {"expected", m.expected},
                     {"actual", m.actual},     {"cycles_matched", m.cycles_matched}};
  }
  if (r.end == cosim::Result::End::kTapeError) {
    j["error"] = {{"block", r.last.error_block},
                  {"offset", r.last.error_offset},
                  {"code", r.last.error_code},
                  {"message", tape_error_message(static_cast<TapeError>(r.last.error_code))}};
  }
  if (!vcd_written.empty()) j["vcd"] = {{"path", vcd_written}, {"from_cycle", vcd_from}, {"to_cycle", vcd_to}};
  j["wall_seconds"] = seconds;
  j["cycles_per_second"] = seconds > 0 ? static_cast<double>(r.cycles) / seconds : 0.0;
  return j;
}

int run(const CosimArgs& a) {
  if (!(a.clock_hz >= 1.0 && a.clock_hz <= 1e11))
    throw std::invalid_argument("--clock-hz must be between 1 and 1e11");
  if (!(a.reader_cps > 0.0)) throw std::invalid_argument("--reader-cps must be positive");
  // Every output reserved before the run (a bad path fails now; a failure leaves none).
  OutputSet outputs;
  outputs.input(a.tape);
  AtomicOutputFile* report_out = outputs.add(a.report);
  AtomicOutputFile* vcd_out = outputs.add(a.vcd);
  const std::vector<uint8_t> frames = tape::load_frames(a.tape);

  cosim::Options o;
  o.config = interp_config(a.clock_hz, {}, a.rapid_mm_min, a.accel_mm_s2);
  o.events = machine_events(a.events, a.clock_hz, a.accel_mm_s2);
  o.config.arch = a.arch;
  o.cycles_per_frame = FrameSource::cycles_per_frame_for(a.clock_hz, a.reader_cps);
  // Default limit: every frame read and every (good) block at its programmed or saturated
  // duration, doubled: no pair of correct engines reaches it.
  const tape::ParseResult readback =
      tape::parse_frames_partial(frames, tape_format_of(o.config));
  o.max_cycles = a.max_cycles ? a.max_cycles
                              : system::cycle_limit_for(readback.program, frames.size(),
                                                        o.cycles_per_frame, o.config) +
                                    last_event_cycle(o.events);
  if (!a.fault.empty()) o.fault = parse_fault(a.fault);
  Progress progress("cosim");
  if (progress.enabled())
    o.progress = [&progress](uint64_t cycle) { progress.show(std::to_string(cycle) + " cycles"); };

  const auto t0 = std::chrono::steady_clock::now();
  const cosim::Result r = cosim::run_lockstep(frames, o);
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  progress.clear();

  std::string vcd_written;
  uint64_t vcd_from = 0, vcd_to = 0;
  if (!a.vcd.empty()) {
    if (r.mismatch) {
      vcd_to = r.mismatch->cycle + 10;
      vcd_from = r.mismatch->cycle > a.vcd_window ? r.mismatch->cycle - a.vcd_window : 1;
      cosim::write_rtl_vcd(frames, o, a.clock_hz, vcd_from, vcd_to, *vcd_out);
      vcd_written = a.vcd;
    } else {
      outputs.discard(vcd_out);
      std::cerr << a.tape << ": no mismatch, so no VCD written (--vcd shows the clocks before a mismatch)\n";
    }
  }
  if (report_out)
    OutputSet::write(report_out, report_json(a, o, r, seconds, vcd_written, vcd_from, vcd_to).dump(2) + "\n");
  outputs.commit();

  if (r.mismatch) {
    std::cerr << a.tape << ": RTL and golden model differ at " << cosim::describe(*r.mismatch) << "\n";
    if (!vcd_written.empty())
      std::cerr << "VCD of the RTL, cycles " << vcd_from << ".." << vcd_to << ": " << vcd_written << "\n";
    return 2;
  }
  if (r.end == cosim::Result::End::kCycleLimit) {
    std::cerr << a.tape << ": stopped at the cycle limit (" << o.max_cycles
              << " cycles) before done or error; the engines agreed so far (--max-cycles)\n";
    return 3;
  }
  if (r.end == cosim::Result::End::kPaused) {
    std::printf("%s: paused after block N%llu at cycle %llu (M00, or M01 with the optional stop on), "
                "position X%lld Y%lld BLU; no cycle start comes (--events start@Ts); RTL and golden "
                "model (%s) agree on every clock\n",
                a.tape.c_str(), static_cast<unsigned long long>(r.last.block_n),
                static_cast<unsigned long long>(r.cycles), static_cast<long long>(r.last.pos_x),
                static_cast<long long>(r.last.pos_y), arch_name(a.arch));
    return kExitPaused;
  }
  if (r.end == cosim::Result::End::kTapeError && is_stop_error(r.last.error_code)) {
    std::printf("%s: %s in block N%llu at cycle %llu, position X%lld Y%lld BLU; RTL and golden model "
                "(%s) agree on every clock\n",
                a.tape.c_str(), tape_error_message(static_cast<TapeError>(r.last.error_code)),
                static_cast<unsigned long long>(r.last.error_block), static_cast<unsigned long long>(r.cycles),
                static_cast<long long>(r.last.pos_x), static_cast<long long>(r.last.pos_y), arch_name(a.arch));
    return kExitStopped;
  }
  if (r.end == cosim::Result::End::kTapeError) {
    std::cerr << a.tape << ": block N" << r.last.error_block << ", offset " << r.last.error_offset
              << ": " << tape_error_message(static_cast<TapeError>(r.last.error_code))
              << " (RTL and golden model agree on every clock)\n";
    return 1;
  }
  std::printf("%s: RTL and golden model (%s) agree on all %llu cycles (%llu blocks, final "
              "position X%lld Y%lld BLU); %.1f M cycles/s\n",
              a.tape.c_str(), arch_name(a.arch), static_cast<unsigned long long>(r.cycles),
              static_cast<unsigned long long>(r.stats.blocks), static_cast<long long>(r.last.pos_x),
              static_cast<long long>(r.last.pos_y),
              seconds > 0 ? static_cast<double>(r.cycles) / seconds / 1e6 : 0.0);
  if (!a.report.empty()) std::printf("report: %s\n", a.report.c_str());
  return 0;
}

void setup(CLI::App& app) {
  auto args = std::make_shared<CosimArgs>();
  CLI::App* cmd = app.add_subcommand(
      "cosim", "Run the verilated RTL and the golden model in lock step, comparing every output every clock");
  cmd->add_option("tape", args->tape, "Tape: .tape (frames with parity) or plain text (.nc)")->required();
  add_arch_option(cmd, args->arch);
  add_rapid_option(cmd, args->rapid_mm_min);
  add_accel_option(cmd, args->accel_mm_s2);
  add_events_option(cmd, args->events);
  cmd->add_option("--report", args->report, "Write the JSON report to this file");
  cmd->add_option("--vcd", args->vcd, "On a mismatch, write a VCD of the RTL around it to this file");
  cmd->add_option("--vcd-window", args->vcd_window, "Cycles before the mismatch in the VCD")
      ->capture_default_str();
  cmd->add_option("--clock-hz", args->clock_hz, "Interpolator clock, Hz")->capture_default_str();
  cmd->add_option("--reader-cps", args->reader_cps, "Tape reader speed, characters per second")
      ->capture_default_str();
  cmd->add_option("--max-cycles", args->max_cycles,
                  "Stop after this many cycles; 0 = a bound from the tape")
      ->capture_default_str();
  cmd->add_option("--inject-fault", args->fault,
                  "Test hook: a fault in the golden model, KIND:CYCLE:AXIS with KIND one of "
                  "lost-pulse, stuck-step, accumulator, wrong-direction and AXIS x or y");
  cmd->callback([args] { run_command("cosim", [&] { return run(*args); }); });
}

const CommandRegistration registration("cosim", setup);

}  // namespace
}  // namespace ncinterp::cli
