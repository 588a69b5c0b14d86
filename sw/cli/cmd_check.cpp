// `ncinterp check TAPE --contour INPUT`: plays the tape on the golden model or the verilated
// RTL and measures, at every pulse, how far the tool is from the programmed blocks (the
// interpolator's error) and from the contour (the total error); checks every pulse against
// the tape and the documented timing; reports per block and overall (docs/verification.md).
// Exit 0 when every rule holds and the total error is within --tol, 2 when the check fails,
// 1 on bad input (one line naming the file, block/line and offset; no output file written).
#include <cstdio>
#include <iostream>
#include <limits>
#include <memory>
#include <optional>
#include <sstream>
#include <stdexcept>

#include "output_set.h"
#include "progress.h"
#include "check_plot.h"
#include "check_report.h"
#include "check_session.h"
#include "command_registry.h"
#include "machine_options.h"
#include "inputs/contour_inputs.h"
#include "tape/tape.h"

namespace ncinterp::cli {
namespace {

struct CheckArgs {
  std::string tape;
  std::string contour;
  double tol_mm = 0.01;
  std::string engine = "golden";
  Arch arch = Arch::kSerial;
  double rapid_mm_min = kDefaultRapidMmMin;
  double accel_mm_s2 = 0;
  std::string events;
  double clock_hz = 1e6;
  double reader_cps = 1000.0;
  std::string svg, report;
  double blu_mm = 0.001;
  unsigned width = 16;
  double cutter_radius_mm = 0.0;
  std::string side = "left";
  std::vector<double> start;
  double airfoil_chord_mm = 100.0;
  double cut_z_mm = std::numeric_limits<double>::quiet_NaN();
  bool every_clock = false;
};

unsigned frac_digits_for(double blu_mm) {
  for (unsigned k = 0; k <= 6; ++k) {
    double p = 1.0;
    for (unsigned i = 0; i < k; ++i) p *= 10.0;
    if (std::abs(blu_mm * p - 1.0) < 1e-9) return k;
  }
  throw std::invalid_argument("--blu must be 1, 0.1, 0.01, ... 0.000001 mm");
}

int run(const CheckArgs& a) {
  // Every output reserved before the work (a bad path fails now; a failure leaves none).
  OutputSet outputs;
  outputs.input(a.tape);
  outputs.input(a.contour);
  AtomicOutputFile* report_out = outputs.add(a.report);
  AtomicOutputFile* svg_out = outputs.add(a.svg);
  checker::CheckSetup setup;
  setup.format.frac_digits = frac_digits_for(a.blu_mm);
  setup.format.inc_width = a.width;
  setup.clock_hz = a.clock_hz;
  setup.reader_cps = a.reader_cps;
  setup.engine = a.engine == "rtl" ? EngineKind::kRtl : EngineKind::kGolden;
  setup.arch = a.arch;
  setup.rapid_mm_min = a.rapid_mm_min;
  setup.accel_mm_s2 = a.accel_mm_s2;
  setup.events = machine_events(a.events, a.clock_hz, a.accel_mm_s2);
  setup.tol_mm = a.tol_mm;
  setup.cutter_radius_mm = a.cutter_radius_mm;
  setup.cutter_left = a.side == "left";
  if (!a.start.empty()) setup.start_mm = firststage::Vec2{a.start[0], a.start[1]};
  setup.keep_pulses = !a.svg.empty();
  setup.every_clock = a.every_clock;
  Progress progress("check");
  if (progress.enabled()) {
    setup.progress = [&progress](uint64_t cycle, uint64_t budget) {
      progress.show(std::to_string(cycle) + " clocks (at most " + std::to_string(budget) + ")");
    };
  }

  const std::vector<uint8_t> frames = tape::load_frames(a.tape);
  std::optional<firststage::Contour> contour;
  if (!a.contour.empty()) {
    firststage::InputOptions io;
    io.airfoil_chord_mm = a.airfoil_chord_mm;
    io.cut_z_mm = a.cut_z_mm;
    contour = firststage::read_contour(a.contour, io);
    for (const std::string& w : contour->warnings) std::cerr << w << "\n";
  }
  if (a.cutter_radius_mm > 0 && !contour)
    throw std::invalid_argument("--cutter-radius needs --contour (the offset contour is built from it)");

  checker::CheckOutcome outcome;
  try {
    outcome = checker::run_check(frames, contour ? &*contour : nullptr, setup);
  } catch (const tape::TapeFormatError& e) {
    std::cerr << a.tape << ": block N" << e.info().block << ", offset " << e.info().offset << ": "
              << e.info().message << "\n";
    throw CommandExit{1};
  }
  progress.clear();

  checker::ReportContext ctx;
  ctx.tape_file = a.tape;
  ctx.contour_file = a.contour;
  ctx.setup = setup;
  if (report_out) OutputSet::write(report_out, checker::check_report_json(outcome, ctx).dump(2) + "\n");
  if (svg_out) OutputSet::write(svg_out, checker::check_svg(outcome, ctx));
  outputs.commit();
  std::cout << checker::check_summary_text(outcome, ctx);
  return !outcome.passed()              ? 2
         : outcome.checker->stopped() ? kExitStopped
         : outcome.checker->paused()  ? kExitPaused
                                      : 0;
}

CommandRegistration registration("check", [](CLI::App& app) {
  auto args = std::make_shared<CheckArgs>();
  CLI::App* cmd = app.add_subcommand(
      "check", "play a tape and measure the pulse path against the programmed blocks and the contour");
  cmd->add_option("TAPE", args->tape, "tape (.tape frames, or .nc/.ngc text)")->required();
  cmd->add_option("--contour", args->contour,
                  "the contour the tape was made from (.json, .nc/.ngc, .dat); without it only the "
                  "interpolator's error and the pulse rules are checked");
  cmd->add_option("--tol", args->tol_mm, "delta: allowed total error, mm")->capture_default_str();
  cmd->add_option("--engine", args->engine, "golden model or verilated RTL")
      ->check(CLI::IsMember({"golden", "rtl"}))
      ->capture_default_str();
  add_arch_option(cmd, args->arch);
  add_rapid_option(cmd, args->rapid_mm_min);
  add_accel_option(cmd, args->accel_mm_s2);
  add_events_option(cmd, args->events);
  cmd->add_option("--clock-hz", args->clock_hz, "interpolator clock, Hz")->capture_default_str();
  cmd->add_option("--reader-cps", args->reader_cps, "tape reader speed, characters per second")
      ->capture_default_str();
  cmd->add_option("--svg", args->svg, "plot: contour, chords, pulse staircase, worst point, error along the path, feed profile (each axis's speed against time)");
  cmd->add_option("--report", args->report, "JSON report: per block and overall errors, feed, violations");
  cmd->add_option("--blu", args->blu_mm, "BLU of the tape, mm (as given to `tape`)")->capture_default_str();
  cmd->add_option("--width", args->width, "increment register width W (as given to `tape`)")
      ->check(CLI::Range(2, 32))
      ->capture_default_str();
  cmd->add_option("--cutter-radius", args->cutter_radius_mm,
                  "the tape is the cutter centre at this radius: total error against the offset contour")
      ->check(CLI::NonNegativeNumber);
  cmd->add_option("--side", args->side, "cutter side of the direction of travel (as given to `tape`)")
      ->check(CLI::IsMember({"left", "right"}))
      ->capture_default_str();
  cmd->add_option("--start", args->start,
                  "where the tape starts, X Y in the contour's mm (default: the contour's start; "
                  "with --cutter-radius give the offset start from the tape report)")
      ->expected(2)
      ->delimiter(',');
  cmd->add_option("--airfoil-chord", args->airfoil_chord_mm, "chord of a .dat airfoil, mm (as given to `tape`)")
      ->capture_default_str();
  cmd->add_option("--cut-z", args->cut_z_mm, "G-code contour with Z: the cutting depth, mm (as given to `tape`)");
  cmd->add_flag("--every-clock", args->every_clock,
                "golden engine: tick every clock instead of passing the clocks where only the "
                "feed phase and the reader's wait advance in one step (same verdict and report, slower)");
  cmd->callback([args]() {
    int code = 0;
    try {
      code = run(*args);
    } catch (const CommandExit&) {
      throw;
    } catch (const std::exception& e) {
      std::cerr << "ncinterp check: " << e.what() << "\n";
      throw CommandExit{1};
    }
    if (code != 0) throw CommandExit{code};
  });
});

}  // namespace
}  // namespace ncinterp::cli
