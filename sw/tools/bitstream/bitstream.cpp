// Bitstream of a board (see bitstream.h).
#include "bitstream.h"

#include <algorithm>
#include <filesystem>
#include <sstream>
#include <stdexcept>

#include "bitstream_build_paths.h"
#include "subprocess.h"
#include "synth_logs.h"

namespace ncinterp::bitstream {
namespace {

using sweep::ProcessOutcome;

std::string failure(const std::string& what, const ProcessOutcome& p, const std::string& log) {
  if (!p.started || p.signal) return what + ": " + p.failure;
  const std::string e = sweep::first_error_line(sweep::read_text_file(log));
  return what + " failed: " + (e.empty() ? "exit code " + std::to_string(p.exit_code) : e) + " (log " + log + ")";
}

std::string yosys_script(const BoardTarget& b, const std::string& json) {
  std::string s = "read_verilog -sv -I\"" + std::string(build::kBoardRtlDir) + "\"";
  for (const char* f : build::kRtlSources) s += std::string(" \"") + f + "\"";
  for (const char* f : build::kBoardSources) s += std::string(" \"") + f + "\"";
  s += "; chparam -set LedActiveLow " + std::to_string(b.board.led_active_low) +
       " -set BitSerial " + (b.board.arch == Arch::kSerial ? "1" : "0") + " -set CircleMode " +
       (b.board.circle_mode ? "1" : "0") + " -set MiscFunctions " + (b.board.misc_functions ? "1" : "0") +
       " -set AccelMmS2 " + std::to_string(static_cast<long>(b.board.accel_mm_s2)) +
       " -set OperatorPins " + (b.board.operator_pins ? "1" : "0") + " board_top";
  // A board without the operator's pins has no such ports: its .pcf names none, and unused
  // inputs would still move the LUT mapping of the whole part.
  if (!b.board.operator_pins) s += "; hierarchy -top board_top; delete -port board_top/*_pin_i";
  // The project's synth_ice40 options (-abc9, timing-driven LUT mapping, is what makes 12 MHz
  // on the UP5K, docs/board.md); -dsp where the part has multipliers.
  s += "; synth_ice40 " + std::string(build::kSynthIce40Options) + (b.board.dsp ? " -dsp" : "") +
       " -top board_top -json \"" +
       json + "\"";
  return s;
}

}  // namespace

BoardTarget board_target(const std::string& name) {
  const board::Board& b = board::board_named(name);
  return {b, {b.pnr_part, "--package", b.package}, std::string(build::kBoardRtlDir) + "/" + b.name + ".pcf"};
}

BitstreamResult build_bitstream(const BoardTarget& b, const std::string& bin_path, const std::string& work_dir,
                                unsigned seeds) {
  BitstreamResult r;
  r.work_dir = work_dir;
  using Failure = BitstreamResult::Failure;
  r.failure = Failure::kTool;  // until the verdict
  std::filesystem::create_directories(work_dir);
  const std::string json = work_dir + "/" + b.board.name + ".json";
  const std::string asc = work_dir + "/" + b.board.name + ".asc";

  const std::string ylog = work_dir + "/yosys.log";
  const ProcessOutcome y = sweep::run_process({"yosys", "-p", yosys_script(b, json)}, ylog);
  if (!y.ok()) {
    r.message = failure("yosys", y, ylog);
    return r;
  }

  std::ostringstream freq;
  freq << b.clock_mhz();
  // Placement is seeded: at this utilisation the Fmax varies by a few % from seed to seed,
  // so seeds 1, 2, ... are tried until one meets the board clock (each run's log is kept).
  double best_fmax = 0;
  unsigned seed = 1;
  for (; seed <= seeds; ++seed) {
    std::vector<std::string> pnr = {"nextpnr-ice40"};
    pnr.insert(pnr.end(), b.pnr_args.begin(), b.pnr_args.end());
    // --timing-allow-fail: a slow placement still gets its Fmax, judged below.
    for (const std::string& a : {std::string("--json"), json, std::string("--pcf"), b.pcf, std::string("--asc"), asc,
                                 std::string("--freq"), freq.str(), std::string("--seed"), std::to_string(seed),
                                 std::string("--timing-allow-fail")})
      pnr.push_back(a);
    const std::string plog = work_dir + "/nextpnr_seed" + std::to_string(seed) + ".log";
    const ProcessOutcome p = sweep::run_process(pnr, plog);
    const sweep::NextpnrReport rep = sweep::parse_nextpnr_log(sweep::read_text_file(plog));
    if (rep.logic_cells) r.logic_cells = static_cast<unsigned>(*rep.logic_cells);
    if (rep.logic_cells_available) r.logic_cells_available = static_cast<unsigned>(*rep.logic_cells_available);
    // Whether it fits does not depend on the seed.
    if (r.logic_cells && r.logic_cells_available && *r.logic_cells > *r.logic_cells_available) {
      r.message = b.board.name + ": does not fit: the design needs " + std::to_string(*r.logic_cells) +
                  " logic cells, the " + b.board.part + " has " + std::to_string(*r.logic_cells_available);
      r.failure = Failure::kDesign;
      return r;
    }
    if (!p.ok()) {
      r.message = failure("nextpnr-ice40", p, plog);
      return r;
    }
    if (!rep.fmax_mhz) {
      r.message = "nextpnr-ice40: no \"Max frequency\" line in " + plog;
      return r;
    }
    best_fmax = std::max(best_fmax, *rep.fmax_mhz);
    r.fmax_mhz = rep.fmax_mhz;
    if (*rep.fmax_mhz >= b.clock_mhz()) break;
  }
  std::ostringstream cells;
  cells << b.board.name << ": " << (r.logic_cells ? std::to_string(*r.logic_cells) : "?") << " of "
        << (r.logic_cells_available ? std::to_string(*r.logic_cells_available) : "?") << " logic cells of the "
        << b.board.part << ", Fmax ";
  if (seed > seeds) {
    r.fmax_mhz = best_fmax;
    cells << best_fmax << " MHz at best over placement seeds 1.." << seeds << " (board clock " << b.clock_mhz()
          << " MHz): misses timing";
    r.message = cells.str();
    r.failure = Failure::kDesign;
    return r;
  }
  cells << *r.fmax_mhz << " MHz (board clock " << b.clock_mhz() << " MHz, placement seed " << seed << ")";

  const std::string ilog = work_dir + "/icepack.log";
  const ProcessOutcome i = sweep::run_process({"icepack", asc, bin_path}, ilog);
  if (!i.ok()) {
    r.message = failure("icepack", i, ilog);
    return r;
  }
  r.failure = Failure::kNone;
  r.message = cells.str();
  return r;
}

}  // namespace ncinterp::bitstream
