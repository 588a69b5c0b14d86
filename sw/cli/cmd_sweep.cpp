// `ncinterp sweep INPUT... --widths LO:HI`: the bit-width exploration (docs/bit-widths.md).
// For every increment-register width W: the tape blocks the first stage needs at --tol, the
// interpolator's and the total error, the worst block time against 1/F and the simulated
// clocks (golden model at W, trajectory checker), the RTL at W in lock step with the golden
// model, and the hardware cost (yosys cells, flip-flops, iCE40 LUTs; nextpnr-ice40 Fmax on
// an HX8K). Widths run in parallel (--jobs); synthesis results are cached per (RTL hash, W).
// Idea: every output is built in memory after the whole sweep and then written atomically,
// so an interrupted or failed sweep leaves no half table. A width whose first stage,
// synthesis or variant build fails gets its row with the reason; only bad options or an
// unreadable input end the command (exit 1, one line naming the file).

#include <cstdio>
#include <filesystem>
#include <iostream>
#include <memory>
#include <thread>

#include "output_set.h"
#include "progress.h"
#include "command_registry.h"
#include "inputs/contour_inputs.h"
#include "sweep_defaults.h"
#include "sweep_plot.h"
#include "sweep_run.h"
#include "sweep_table.h"

namespace ncinterp::cli {
namespace {

struct SweepArgs {
  std::vector<std::string> inputs;
  std::string widths;
  std::string arcs = "chords";
  firststage::FirstStageOptions first_stage;
  double airfoil_chord_mm = 100.0;
  double clock_hz = 1e6;
  double reader_cps = 1000.0;
  std::string csv, svg, markdown;
  unsigned jobs = 0;
  bool no_synth = false, no_rtl = false;
  std::string cache;
  double pnr_mhz = 50.0;
};

// The columns of the tables in docs/bit-widths.md (--markdown; the third has the blocks of
// every input).
const std::vector<std::string> kTapeColumns = {"width", "blocks", "tape_frames", "path_error_max_blu",
                                               "total_error_max_mm", "check", "feed_error_worst", "cycles",
                                               "rtl_cosim"};
const std::vector<std::string> kHardwareColumns = {"width", "cells", "flip_flops", "ice40_luts",
                                                   "ice40_logic_cells", "fmax_mhz"};

int run(const SweepArgs& a) {
  using namespace ncinterp::sweep;
  SweepSetup setup;
  setup.widths = parse_width_range(a.widths);
  setup.measure.first_stage = a.first_stage;
  setup.measure.first_stage.arcs_circle = a.arcs == "circle";
  setup.measure.clock_hz = a.clock_hz;
  setup.measure.reader_cps = a.reader_cps;
  firststage::validate_options(a.first_stage);  // the width is checked per row
  if (!(a.clock_hz > 0)) throw std::invalid_argument("--clock-hz must be > 0");
  if (!(a.reader_cps > 0)) throw std::invalid_argument("--reader-cps must be > 0");
  setup.jobs = a.jobs;
  setup.synthesis = !a.no_synth;
  setup.synth = default_synthesis_setup(a.cache);
  setup.synth.pnr_target_mhz = a.pnr_mhz;
  setup.rtl = !a.no_rtl;
  setup.rtl_variant = default_rtl_variant_setup(a.cache);
  setup.rtl_variant.clock_hz = a.clock_hz;
  setup.rtl_variant.reader_cps = a.reader_cps;
  setup.tape_dir = default_tape_dir(a.cache);

  // Every output reserved before the sweep (a bad path fails now; a failure leaves none).
  OutputSet outputs;
  for (const std::string& path : a.inputs) outputs.input(path);
  AtomicOutputFile* csv_out = outputs.add(a.csv);
  AtomicOutputFile* markdown_out = outputs.add(a.markdown);
  AtomicOutputFile* svg_out = outputs.add(a.svg);

  firststage::InputOptions io;
  io.airfoil_chord_mm = a.airfoil_chord_mm;
  for (const std::string& path : a.inputs) setup.inputs.push_back({path, firststage::read_contour(path, io)});

  Progress line("sweep");
  ProgressCallback progress;
  if (line.enabled()) {
    progress = [&line](const SweepProgress& p) {
      line.show(std::to_string(p.widths_done) + "/" + std::to_string(p.widths_total) + " widths done; W=" +
                    std::to_string(p.width) + ": " + p.stage,
                true);  // stages change seldom: each is shown
    };
  }
  const std::vector<SweepRow> rows = run_sweep(setup, progress);
  line.clear();
  // Points (width, input) the first stage refused: each named once on stderr; a sweep in
  // which nothing could be measured is a failed run (exit 1, no output).
  size_t refused = 0, points = 0;
  for (const SweepRow& r : rows)
    for (const InputResult& in : r.inputs) {
      ++points;
      if (in.measured()) continue;
      ++refused;
      std::cerr << "sweep: W=" << r.width << ", " << in.input << ": refused: " << in.failure << "\n";
    }
  if (points > 0 && refused == points)
    throw std::runtime_error("no width of --widths " + a.widths + " could tape any input (see above)");

  const Table table = sweep_table(rows);
  const std::string csv = a.csv.empty() ? "" : to_csv(table);
  std::vector<std::string> input_columns = {"width"};
  for (const std::string& h : table.header)
    if (h.rfind("blocks ", 0) == 0) input_columns.push_back(h);
  const std::string markdown = a.markdown.empty() ? ""
                                                  : to_markdown(table, kTapeColumns) + "\n" +
                                                        to_markdown(table, input_columns) + "\n" +
                                                        to_markdown(table, kHardwareColumns);
  std::string svg;
  if (!a.svg.empty()) {
    PlotContext ctx;
    ctx.blu_mm = a.first_stage.blu_mm;
    ctx.tol_mm = a.first_stage.tol_mm;
    ctx.title = "ncinterp sweep --widths " + a.widths + " (" + std::to_string(a.inputs.size()) + " inputs)";
    svg = plot::render_svg(sweep_figure(rows, ctx));
  }
  OutputSet::write(csv_out, csv);
  OutputSet::write(markdown_out, markdown);
  OutputSet::write(svg_out, svg);
  outputs.commit();
  std::cout << to_markdown(table, kTapeColumns) << "\n" << to_markdown(table, kHardwareColumns);
  return 0;
}

CommandRegistration registration("sweep", [](CLI::App& app) {
  auto args = std::make_shared<SweepArgs>();
  CLI::App* cmd = app.add_subcommand(
      "sweep", "bit-width exploration: tape length, errors, feed accuracy, area and Fmax for every width W");
  cmd->add_option("INPUT", args->inputs, "contours (.json, .nc/.ngc, .dat)")->required()->expected(1, -1);
  cmd->add_option("--widths", args->widths, "increment register widths LO:HI (bits, 2..32)")->required();
  cmd->add_option("--tol", args->first_stage.tol_mm, "delta: allowed total error, mm")->capture_default_str();
  cmd->add_option("--method", args->first_stage.method, "chord method (Tamm 1, 2 or 3)")
      ->check(CLI::IsMember({1, 2, 3}))
      ->capture_default_str();
  cmd->add_option("--arcs", args->arcs, "arcs of the contour as chords or as quadrant arc blocks (G02/G03)")
      ->check(CLI::IsMember({"chords", "circle"}))
      ->capture_default_str();
  cmd->add_option("--blu", args->first_stage.blu_mm, "basic length unit, mm")->capture_default_str();
  cmd->add_option("--feed", args->first_stage.feed_mm_min, "feed, mm/min")->capture_default_str();
  cmd->add_option("--airfoil-chord", args->airfoil_chord_mm, "chord of a .dat airfoil, mm")->capture_default_str();
  cmd->add_option("--clock-hz", args->clock_hz, "interpolator clock, Hz")->capture_default_str();
  cmd->add_option("--reader-cps", args->reader_cps, "tape reader speed, characters per second")
      ->capture_default_str();
  cmd->add_option("--csv", args->csv, "table, one row per width");
  cmd->add_option("--svg", args->svg, "plot: area, Fmax, tape length, errors, feed accuracy, clocks against W");
  cmd->add_option("--markdown", args->markdown, "the tables of docs/bit-widths.md");
  cmd->add_option("--jobs", args->jobs, "widths measured in parallel (default: one per core)")
      ->check(CLI::PositiveNumber);
  cmd->add_flag("--no-synth", args->no_synth, "skip yosys and nextpnr (their columns say so)");
  cmd->add_flag("--no-rtl", args->no_rtl, "skip the verilated RTL variants (their column says so)");
  cmd->add_option("--cache", args->cache, "cache and work directory (default: <build>/sweep-cache)");
  cmd->add_option("--pnr-freq", args->pnr_mhz, "nextpnr timing target, MHz")->capture_default_str();
  cmd->callback([args]() {
    try {
      run(*args);
    } catch (const firststage::InputError& e) {
      std::cerr << e.what() << "\n";
      throw CommandExit{1};
    } catch (const std::exception& e) {
      std::cerr << "ncinterp sweep: " << e.what() << "\n";
      throw CommandExit{1};
    }
  });
});

}  // namespace
}  // namespace ncinterp::cli
