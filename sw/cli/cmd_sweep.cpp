// `ncinterp sweep`: design-space exploration over the interpolator's parameters
// (docs/bit-widths.md). A grid (--widths, --feed-widths, --pos-widths, --blu, --clock-hz,
// --param NAME=VALUES; each a list or range) of design points, each measured for what it
// costs (yosys cells, flip-flops, iCE40 LUTs; nextpnr-ice40 logic cells and Fmax on the
// HX8K and the HX1K) and what it buys (tape length, interpolator and total error, feed
// accuracy, clocks from the first stage + golden model + checker; the register ranges),
// then the Pareto front and a recommendation per board.
// Three ways to run the same per-point code (point_run.h):
//   in process:  ncinterp sweep INPUT... --widths 8:16 [--jobs N] --cache DIR [outputs]
//   planned:     ncinterp sweep INPUT... --widths 8:16 --plan [--slurm] --cache DIR
//                (DIR/jobs.txt: one `ncinterp sweep --run-one KEY --cache DIR` per point,
//                 for GNU parallel or a Slurm job array), then
//                ncinterp sweep --collect DIR [outputs]
// Idea: every point's result is a content-addressed file in DIR/points (point_store.h), so
// a point already measured is never measured again, runners need no coordination, and the
// collected tables do not depend on the order or the machine. Every output is built in
// memory and written atomically; bad options or an unreadable input end the command (exit
// 1, one line naming the file), a point that fails keeps its reason in its row.

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <memory>
#include <nlohmann/json.hpp>
#include <sstream>

#include "atomic_file.h"
#include "output_set.h"
#include "progress.h"
#include "command_registry.h"
#include "grid_report.h"
#include "inputs/contour_inputs.h"
#include "pareto.h"
#include "point_store.h"
#include "sweep_defaults.h"
#include "sweep_plot.h"
#include "sweep_run.h"
#include "sweep_table.h"
#include "synth_cache.h"

namespace ncinterp::cli {
namespace {

using nlohmann::json;
using namespace ncinterp::sweep;

struct SweepArgs {
  std::vector<std::string> inputs;
  // Grid axes, as given ("" = not an axis: the default).
  std::string widths, feed_widths, pos_widths, blu, clock_hz, archs;
  std::vector<std::string> params;  // NAME=VALUES
  std::string arcs = "chords";
  double tol_mm = 0.01, feed_mm_min = 1000.0;
  int method = 3;
  double airfoil_chord_mm = 100.0;
  double reader_cps = 1000.0;
  std::string csv, svg, markdown, pareto_csv, pareto_md, pareto_svg, times;
  unsigned jobs = 0;
  bool no_synth = false, no_rtl = false;
  std::string cache;
  double pnr_mhz = 50.0;
  bool plan = false, slurm = false;
  std::string run_one, collect;
};

// The columns of the tables in docs/bit-widths.md (--markdown; the third has the blocks of
// every input); the axes go in front.
const std::vector<std::string> kTapeColumns = {"blocks", "tape_frames", "path_error_max_blu", "total_error_max_mm",
                                               "check", "feed_error_worst", "cycles", "rtl_cosim"};
const std::vector<std::string> kHardwareColumns = {"cells", "flip_flops", "ice40_luts", "ice40_logic_cells",
                                                   "fmax_mhz", "hx1k_logic_cells", "hx1k_fmax_mhz"};
const std::vector<std::string> kRangeColumns = {"max_move_mm", "pos_range_mm", "feed_min_mm_min", "feed_max_mm_min",
                                                "feed_max_clock_mm_min"};

// What a point's result depends on among the options (the grid is in the points).
json settings_json(const SweepArgs& a) {
  std::vector<std::string> inputs;
  for (const std::string& in : a.inputs) inputs.push_back(std::filesystem::absolute(in).lexically_normal().string());
  return {{"inputs", inputs},          {"tol_mm", a.tol_mm},       {"method", a.method},
          {"arcs", a.arcs},            {"feed_mm_min", a.feed_mm_min}, {"airfoil_chord_mm", a.airfoil_chord_mm},
          {"reader_cps", a.reader_cps}, {"no_synth", a.no_synth},  {"no_rtl", a.no_rtl},
          {"pnr_mhz", a.pnr_mhz}};
}

// The point setup from the plan's settings: reads the inputs, runs the tools' version
// queries for the synthesis key.
PointSetup point_setup(const json& s, const std::string& cache) {
  PointSetup p;
  firststage::FirstStageOptions& fs = p.measure.first_stage;
  fs.tol_mm = s.at("tol_mm").get<double>();
  fs.method = s.at("method").get<int>();
  fs.arcs_circle = s.at("arcs").get<std::string>() == "circle";
  fs.feed_mm_min = s.at("feed_mm_min").get<double>();
  firststage::validate_options(fs);
  if (!(fs.feed_mm_min > 0)) throw std::invalid_argument("--feed must be > 0");
  p.measure.reader_cps = s.at("reader_cps").get<double>();
  if (!(p.measure.reader_cps > 0)) throw std::invalid_argument("--reader-cps must be > 0");
  firststage::InputOptions io;
  io.airfoil_chord_mm = s.at("airfoil_chord_mm").get<double>();
  for (const std::string& path : s.at("inputs").get<std::vector<std::string>>())
    p.inputs.push_back({path, firststage::read_contour(path, io)});
  p.synthesis = !s.at("no_synth").get<bool>();
  p.synth = default_synthesis_setup(cache);
  p.synth.pnr_target_mhz = s.at("pnr_mhz").get<double>();
  if (p.synthesis) p.synth_key = synthesis_key(p.synth);
  p.rtl = !s.at("no_rtl").get<bool>();
  p.rtl_variant = default_rtl_variant_setup(cache);
  p.rtl_variant.reader_cps = p.measure.reader_cps;
  p.tape_dir = default_tape_dir(cache);
  return p;
}

std::vector<GridAxis> grid_axes(const SweepArgs& a) {
  std::vector<GridAxis> axes;
  auto axis = [&axes](const char* name, const std::string& option, const std::string& text, double lo, double hi,
                      const char* unit) {
    if (!text.empty()) axes.push_back({name, parse_values(option, text, lo, hi, unit)});
  };
  axis(kIncWidth, "--widths", a.widths, kMinWidth, kMaxWidth, "bits");
  axis(kFeedWidth, "--feed-widths", a.feed_widths, 8, 48, "bits");
  axis(kPosWidth, "--pos-widths", a.pos_widths, 8, 48, "bits");
  axis(kBlu, "--blu", a.blu, 1e-6, 1, "mm");
  axis(kClock, "--clock-hz", a.clock_hz, 1, 1e10, "Hz");
  if (!a.archs.empty()) {
    // The arch is interp_top's BitSerial: 1 serial, 0 parallel, in the order given.
    GridAxis arch{kBitSerial, {}};
    std::stringstream list(a.archs);
    for (std::string name; std::getline(list, name, ',');) {
      const double v = parse_arch(name) == Arch::kSerial ? 1 : 0;
      if (std::find(arch.values.begin(), arch.values.end(), v) != arch.values.end())
        throw std::invalid_argument("--archs: " + name + " is given twice");
      arch.values.push_back(v);
    }
    axes.push_back(arch);
  }
  for (const std::string& p : a.params) {
    const size_t eq = p.find('=');
    if (eq == std::string::npos || eq == 0) throw std::invalid_argument("--param: '" + p + "' is not NAME=VALUES");
    axis(p.substr(0, eq).c_str(), "--param " + p.substr(0, eq), p.substr(eq + 1), 0, 1e15, "");
  }
  if (axes.empty()) throw std::invalid_argument("no grid: give --widths (and any of the other axes)");
  return axes;
}

Plan make_plan(const SweepArgs& a, const PointSetup& setup) {
  Plan plan;
  plan.settings = settings_json(a);
  plan.inputs = plan.settings.at("inputs").get<std::vector<std::string>>();
  const std::vector<GridAxis> axes = grid_axes(a);
  for (const GridAxis& g : axes) plan.axes.push_back(g.name);
  std::vector<std::string> settings;
  for (const auto& [name, value] : plan.settings.items())
    if (name != "inputs") settings.push_back(name + "=" + value.dump());
  const std::string hash = setup_hash(setup, settings, model_source_files());
  for (const DesignPoint& p : expand_grid(axes)) plan.points.push_back({p, point_key(p, hash)});
  return plan;
}

std::string self_path() {
  std::error_code ec;
  const std::filesystem::path p = std::filesystem::read_symlink("/proc/self/exe", ec);
  return ec ? std::string("ncinterp") : p.string();
}

// DIR/jobs.txt, and with --slurm DIR/sweep.sbatch (a job array, one task per line).
void write_jobs(const Plan& plan, const std::string& dir, bool slurm) {
  const std::string exe = self_path();
  std::string jobs;
  for (const PlannedPoint& p : plan.points) jobs += exe + " sweep --run-one " + p.key + " --cache " + dir + "\n";
  write_file_atomically(dir + "/jobs.txt", jobs);
  if (!slurm) return;
  const std::string script =
      "#!/bin/bash\n"
      "# Generated by `ncinterp sweep --plan --slurm`: one array task per design point of\n"
      "# " + dir + "/plan.json. Submit: sbatch " + dir + "/sweep.sbatch; then\n"
      "# ncinterp sweep --collect " + dir + ". A point already measured returns at once.\n"
      "#SBATCH --job-name=ncinterp-sweep\n"
      "#SBATCH --array=1-" + std::to_string(plan.points.size()) + "\n"
      "#SBATCH --ntasks=1\n"
      "#SBATCH --cpus-per-task=1\n"
      "#SBATCH --output=" + dir + "/slurm/%A_%a.out\n"
      "set -euo pipefail\n"
      "line=$(sed -n \"${SLURM_ARRAY_TASK_ID}p\" " + dir + "/jobs.txt)\n"
      "exec bash -c \"$line\"\n";
  std::filesystem::create_directories(dir + "/slurm");
  write_file_atomically(dir + "/sweep.sbatch", script);
}

std::vector<std::string> with_axes(const std::vector<std::string>& axes, const std::vector<std::string>& columns) {
  std::vector<std::string> c = axes;
  if (std::find(axes.begin(), axes.end(), kIncWidth) == axes.end()) c.insert(c.begin(), "width");
  c.insert(c.end(), columns.begin(), columns.end());
  return c;
}

// The files a sweep writes, reserved before any point is measured (a bad path fails at
// once; a failure later leaves none of them).
struct ReportOutputs {
  OutputSet set;
  AtomicOutputFile *csv, *markdown, *pareto_csv, *pareto_md, *times, *pareto_svg, *svg;
  explicit ReportOutputs(const SweepArgs& a) {
    for (const std::string& path : a.inputs) set.input(path);
    csv = set.add(a.csv);
    markdown = set.add(a.markdown);
    pareto_csv = set.add(a.pareto_csv);
    pareto_md = set.add(a.pareto_md);
    times = set.add(a.times);
    pareto_svg = set.add(a.pareto_svg);
    svg = set.add(a.svg);
  }
};

// Points (input) the first stage refused: each named once on stderr; a grid in which
// nothing could be measured is a failed run (exit 1, no output).
void name_refused_points(const std::vector<PointResult>& results) {
  size_t refused = 0, measured = 0;
  for (const PointResult& r : results)
    for (const InputResult& in : r.row.inputs) {
      if (in.measured()) {
        ++measured;
        continue;
      }
      ++refused;
      std::cerr << "sweep: " << point_text(r.point) << ", " << in.input << ": refused: " << in.failure << "\n";
    }
  if (refused > 0 && measured == 0)
    throw std::runtime_error("no point of the grid could tape any input (see above)");
}

// Tables, front, recommendations and figures of the collected results, into the reserved
// files, committed together after all are built.
void report(const SweepArgs& a, const Plan& plan, const std::vector<PointResult>& results, ReportOutputs& out) {
  name_refused_points(results);
  const Table table = grid_table(results, plan.axes);
  const ParetoFront front = pareto_front(results);
  const Table front_t = front_table(table, front, plan.axes);
  const Table recs = recommendation_table(results, recommend(results, front, MeasureSetup{}.clock_hz));
  std::vector<std::string> input_columns = with_axes(plan.axes, {});
  for (const std::string& h : table.header)
    if (h.rfind("blocks ", 0) == 0) input_columns.push_back(h);
  const std::string front_note = "Pareto front over " + std::to_string(front.objectives.size()) + " objectives (" +
                                 [&] {
                                   std::string s;
                                   for (const std::string& o : front.objectives) s += (s.empty() ? "" : ", ") + o;
                                   return s;
                                 }() +
                                 "): " + std::to_string(front.members.size()) + " of " +
                                 std::to_string(front.eligible) + " points that passed with every objective measured (" +
                                 std::to_string(results.size()) + " in the grid)\n\n";
  const std::string front_md = front_note + to_markdown(front_t) + "\nRecommendation per board:\n\n" + to_markdown(recs);

  if (out.csv) OutputSet::write(out.csv, to_csv(table));
  if (out.markdown)
    OutputSet::write(out.markdown, to_markdown(table, with_axes(plan.axes, kTapeColumns)) + "\n" +
                                       to_markdown(table, input_columns) + "\n" +
                                       to_markdown(table, with_axes(plan.axes, kHardwareColumns)) + "\n" +
                                       to_markdown(table, with_axes(plan.axes, kRangeColumns)));
  if (out.pareto_csv) OutputSet::write(out.pareto_csv, to_csv(front_t));
  if (out.pareto_md) OutputSet::write(out.pareto_md, front_md);
  if (out.times) OutputSet::write(out.times, to_csv(timing_table(results)));
  if (out.pareto_svg)
    OutputSet::write(out.pareto_svg, plot::render_svg(pareto_figure(
                                         results, front, "ncinterp sweep: Pareto front, " +
                                                             std::to_string(results.size()) + " design points")));
  if (out.svg) {
    if (plan.axes != std::vector<std::string>{kIncWidth})
      throw std::invalid_argument("--svg draws against W and needs a grid over --widths alone; use --pareto-svg");
    std::vector<SweepRow> rows;
    for (const PointResult& r : results) rows.push_back(r.row);
    PlotContext ctx;
    ctx.blu_mm = 0.001;
    ctx.tol_mm = plan.settings.at("tol_mm").get<double>();
    ctx.title = "ncinterp sweep (" + std::to_string(plan.inputs.size()) + " inputs)";
    OutputSet::write(out.svg, plot::render_svg(sweep_figure(rows, ctx)));
  }
  out.set.commit();
  std::cout << to_markdown(table, with_axes(plan.axes, kTapeColumns)) << "\n"
            << to_markdown(table, with_axes(plan.axes, kHardwareColumns)) << "\n"
            << front_md;
}

std::string cache_dir(const SweepArgs& a) {
  const std::string d = a.cache.empty() ? default_cache_dir() : a.cache;
  return std::filesystem::absolute(d).lexically_normal().string();
}

int run(const SweepArgs& a) {
  const std::string dir = cache_dir(a);
  if (!a.run_one.empty()) {
    const Plan plan = read_plan(dir);
    const PointSetup setup = point_setup(plan.settings, dir);
    const bool ran = run_one_point(plan, dir, setup, a.run_one);
    std::cerr << "ncinterp sweep: point " << a.run_one << (ran ? " measured" : " already measured") << "\n";
    return 0;
  }
  if (!a.collect.empty()) {
    const std::string cdir = std::filesystem::absolute(a.collect).lexically_normal().string();
    ReportOutputs out(a);
    const Plan plan = read_plan(cdir);
    report(a, plan, collect_results(cdir, plan), out);
    return 0;
  }
  if (a.inputs.empty()) throw std::invalid_argument("INPUT is required (or --run-one KEY / --collect DIR)");
  if (a.slurm && !a.plan) throw std::invalid_argument("--slurm writes a job array with --plan");
  const PointSetup setup = point_setup(settings_json(a), dir);
  std::unique_ptr<ReportOutputs> out;
  if (!a.plan) out = std::make_unique<ReportOutputs>(a);  // before any point is measured
  const Plan plan = make_plan(a, setup);
  write_plan(dir, plan);
  if (a.plan) {
    write_jobs(plan, dir, a.slurm);
    std::cout << plan.points.size() << " points planned: " << dir << "/jobs.txt"
              << (a.slurm ? ", " + dir + "/sweep.sbatch" : "") << "\n";
    return 0;
  }
  Progress line("sweep");
  ProgressCallback progress;
  if (line.enabled()) {
    progress = [&line](const SweepProgress& p) {
      line.show(std::to_string(p.points_done) + "/" + std::to_string(p.points_total) + " points done; " + p.point +
                    ": " + p.stage,
                true);  // stages change seldom: each is shown
    };
  }
  const size_t ran = run_missing_points(plan, dir, setup, a.jobs, progress);
  line.clear();
  std::cerr << "ncinterp sweep: " << ran << " of " << plan.points.size() << " points measured, "
            << plan.points.size() - ran << " from " << dir << "/points\n";
  report(a, plan, collect_results(dir, plan), *out);
  return 0;
}

CommandRegistration registration("sweep", [](CLI::App& app) {
  auto args = std::make_shared<SweepArgs>();
  CLI::App* cmd = app.add_subcommand(
      "sweep", "design-space exploration: a grid of parameters, each point's cost and accuracy, the Pareto front");
  cmd->add_option("INPUT", args->inputs, "contours (.json, .nc/.ngc, .dat)")->expected(0, -1);
  cmd->add_option("--widths", args->widths, "IncWidth: list or range, e.g. 8:16 or 12,16 (bits, 2..32)");
  cmd->add_option("--feed-widths", args->feed_widths, "FeedWidth (F register): list or range, bits");
  cmd->add_option("--pos-widths", args->pos_widths, "PosWidth (position counters): list or range, bits");
  cmd->add_option("--blu", args->blu, "basic length unit, mm: list, e.g. 0.001,0.01 (sets FracDigits)");
  cmd->add_option("--clock-hz", args->clock_hz, "interpolator clock, Hz: list (default 1e6)");
  cmd->add_option("--archs", args->archs,
                  "microarchitectures: serial, parallel or both (serial,parallel); the RTL parameter "
                  "BitSerial, which the golden model and the RTL variants follow (default: serial)");
  cmd->add_option("--param", args->params, "any other RTL parameter: NAME=VALUES (list or range)");
  cmd->add_option("--tol", args->tol_mm, "delta: allowed total error, mm")->capture_default_str();
  cmd->add_option("--method", args->method, "chord method (Tamm 1, 2 or 3)")
      ->check(CLI::IsMember({1, 2, 3}))
      ->capture_default_str();
  cmd->add_option("--arcs", args->arcs, "arcs of the contour as chords or as quadrant arc blocks (G02/G03)")
      ->check(CLI::IsMember({"chords", "circle"}))
      ->capture_default_str();
  cmd->add_option("--feed", args->feed_mm_min, "feed, mm/min")->capture_default_str();
  cmd->add_option("--airfoil-chord", args->airfoil_chord_mm, "chord of a .dat airfoil, mm")->capture_default_str();
  cmd->add_option("--reader-cps", args->reader_cps, "tape reader speed, characters per second")
      ->capture_default_str();
  cmd->add_option("--csv", args->csv, "table, one row per design point");
  cmd->add_option("--svg", args->svg, "plot against W (a grid over --widths alone)");
  cmd->add_option("--markdown", args->markdown, "the tables of docs/bit-widths.md");
  cmd->add_option("--pareto-csv", args->pareto_csv, "the Pareto front, one row per point");
  cmd->add_option("--pareto-md", args->pareto_md, "the Pareto front and the recommendation per board");
  cmd->add_option("--pareto-svg", args->pareto_svg, "plot: area against error and tape length, the front marked");
  cmd->add_option("--times", args->times, "CSV: wall time of every point where it ran");
  cmd->add_option("--jobs", args->jobs, "points measured in parallel in this process (default: one per core)")
      ->check(CLI::PositiveNumber);
  cmd->add_flag("--no-synth", args->no_synth, "skip yosys and nextpnr (their columns say so)");
  cmd->add_flag("--no-rtl", args->no_rtl, "skip the verilated RTL variants (their column says so)");
  cmd->add_option("--cache", args->cache, "plan, results, cache and work directory (default: <build>/sweep-cache)");
  cmd->add_option("--pnr-freq", args->pnr_mhz, "nextpnr timing target, MHz")->capture_default_str();
  cmd->add_flag("--plan", args->plan, "write the plan and DIR/jobs.txt (one --run-one per point), run nothing");
  cmd->add_flag("--slurm", args->slurm, "with --plan: also DIR/sweep.sbatch, a Slurm job array over jobs.txt");
  cmd->add_option("--run-one", args->run_one, "measure one planned point (KEY from jobs.txt) into --cache DIR");
  cmd->add_option("--collect", args->collect, "merge the results in DIR into the tables and plots");
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
