// `ncinterp tape INPUT -o OUT.tape`: the first stage (sw/host/firststage, docs/first-stage.md).
// Reads a contour (.json contour or reference-point table, .nc/.ngc/.gcode/.tap G-code, .dat
// airfoil), replaces it by chords within --tol (Tamm's method 1, 2 or 3) or quadrant arc
// blocks, offsets it for the cutter, rounds it to the BLU grid and writes the tape:
// traverses as G00 blocks, a G-code program's cutting depths as one pass each.
// Idea: everything is built and checked in memory first (the tape text is read back with
// the project's own tape reader, the deviation of the chord path from the contour is
// measured), then each output is written atomically; a failure leaves no file behind.
// With --accel the arcs are fed at most at sqrt(A R) (their centripetal acceleration within
// A) and the feed is planned (sc_model/checker/feed_plan.h): the tape's cycle time at exact
// stop on the 12 MHz board machine, and what continuous mode would take.
// Exit 0 on success; 1 on bad input (one line "FILE:LINE: what is wrong") or options.
#include <chrono>
#include <cmath>
#include <cstdio>
#include <iostream>
#include <limits>
#include <memory>
#include <optional>
#include <nlohmann/json.hpp>
#include <stdexcept>

#include "output_set.h"
#include "command_registry.h"
#include "boards.h"
#include "feed_plan.h"
#include "firststage.h"
#include "inputs/contour_inputs.h"
#include "measure/deviation_meter.h"
#include "tape/tape.h"

namespace ncinterp::cli {
namespace {

using namespace ncinterp::firststage;

struct TapeArgs {
  std::string input, output, report;
  std::string board;  // the tape is meant for this board (boards.h): refused if it cannot play it
  std::string arcs = "chords", side = "left";
  FirstStageOptions options;
  double airfoil_chord_mm = 100.0;
  double cut_z_mm = std::numeric_limits<double>::quiet_NaN();
  checker::FeedPlanOptions plan;
};

// The machine the feed plan is made for: the boards' 12 MHz oscillator (boards.cpp).
constexpr double kPlanClockHz = 12e6;

// The feed plan's figures for the report.
nlohmann::json plan_json(const checker::FeedPlan& p, const checker::FeedPlanOptions& o) {
  nlohmann::json continuous = nlohmann::json::array();
  for (const checker::ContinuousPlan& c : p.continuous)
    continuous.push_back({{"lookahead_blocks", c.lookahead == 0 ? nlohmann::json("all") : nlohmann::json(c.lookahead)},
                          {"seconds", c.seconds}});
  return {{"accel_mm_s2", o.accel_mm_s2},
          {"junction_deviation_mm", o.junction_deviation_mm},
          {"clock_hz", kPlanClockHz},
          {"programmed_seconds", p.programmed_s},
          {"exact_stop_seconds", p.exact_stop_s},
          {"continuous_planned_only", continuous}};
}

double seconds_since(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

nlohmann::json mm_point(GridPoint g, double blu_mm) {
  return nlohmann::json::array({g.x * blu_mm, g.y * blu_mm});
}

// Why the board's interpolator (boards.h) cannot play a tape written with these options,
// or "" when it can.
std::string board_refusal(const board::Board& b, const FirstStageOptions& o) {
  const InterpConfig cfg = board::board_interp_config(b, b.clock_hz);
  const tape::Format f = tape_format(o), want = tape_format_of(cfg);
  const std::string board = "--board " + b.name + ": ";
  if (o.arcs_circle && !b.circle_mode)
    return board + "its interpolator is built without circle mode (lines only, to fit the " + b.part +
           "): write the arcs as chords (--arcs chords)";
  if (f.inc_width != want.inc_width)
    return board + "its increment registers are " + std::to_string(want.inc_width) + " bits: --width " +
           std::to_string(want.inc_width);
  if (f.frac_digits != want.frac_digits)
    return board + "it counts in BLU of 10^-" + std::to_string(want.frac_digits) + " mm: --blu " +
           (want.frac_digits == 3 ? std::string("0.001") : "1e-" + std::to_string(want.frac_digits));
  if (f.feed_width > want.feed_width)
    return board + "its F register is " + std::to_string(want.feed_width) + " bits";
  if (o.tool && !b.misc_functions)
    return board + "its interpolator is built without M03 and M05 (to fit the " + b.part + "): leave out --tool";
  return "";
}

// Per cutting pass: its depth, its blocks (traverses included) and the length cut and
// traversed. A move belongs to the pass of its input element; the offset's joins (element
// -1) to the pass of the move before them.
struct PassFigures {
  double depth_mm = 0.0;
  long blocks = 0, traverse_blocks = 0;
  long first_block = 0;  // N of the pass's first block (0: none)
  double cut_mm = 0.0, traverse_mm = 0.0;
};

std::vector<PassFigures> pass_figures(const Contour& c, const FirstStageResult& res, double blu_mm) {
  std::vector<CutPass> passes = c.passes;
  if (passes.empty())
    passes.push_back({std::numeric_limits<double>::quiet_NaN(), 0, static_cast<int>(c.element_names.size())});
  std::vector<PassFigures> out(passes.size());
  for (size_t p = 0; p < passes.size(); ++p) out[p].depth_mm = passes[p].depth_mm;
  size_t p = 0;
  GridPoint cur = res.start;
  long n = 0;
  for (const Move& m : res.moves) {
    ++n;
    if (m.element >= 0)
      while (p + 1 < passes.size() && m.element >= passes[p].end_element) ++p;
    PassFigures& f = out[p];
    if (f.blocks++ == 0) f.first_block = n;
    const double len = move_length_mm(cur, m, blu_mm);
    if (m.rapid) {
      ++f.traverse_blocks;
      f.traverse_mm += len;
    } else {
      f.cut_mm += len;
    }
    cur = m.to;
  }
  return out;
}

std::string depth_text(double depth_mm) {
  if (std::isnan(depth_mm)) return "no Z";
  char buf[32];
  std::snprintf(buf, sizeof buf, "Z%g", depth_mm);
  return buf;
}

int run(TapeArgs a) {
  FirstStageOptions& o = a.options;
  o.arcs_circle = a.arcs == "circle";
  o.side_left = a.side == "left";
  // A board that ramps tapes and plans for its own limit unless --accel says otherwise.
  if (o.accel_mm_s2 == 0 && !a.board.empty()) o.accel_mm_s2 = board::board_named(a.board).accel_mm_s2;
  validate_options(o);
  if (!a.board.empty()) {
    const std::string why = board_refusal(board::board_named(a.board), o);
    if (!why.empty()) throw std::invalid_argument(why);
  }
  // Every output reserved before the work: a bad output path fails now, and a failure
  // later leaves none of them.
  OutputSet outputs;
  outputs.input(a.input);
  AtomicOutputFile* tape_out = outputs.add(a.output);
  AtomicOutputFile* report_out = outputs.add(a.report);
  const auto t0 = std::chrono::steady_clock::now();
  InputOptions io;
  io.airfoil_chord_mm = a.airfoil_chord_mm;
  io.cut_z_mm = a.cut_z_mm;
  const Contour contour = read_contour(a.input, io);
  for (const std::string& w : contour.warnings) std::cerr << w << "\n";
  const auto t_read = std::chrono::steady_clock::now();
  const FirstStageResult res = run_first_stage(contour, o);
  for (const std::string& w : res.warnings) std::cerr << w << "\n";
  const double stage_s = seconds_since(t_read);

  // The tape, in memory, read back by the project's reader: what it reads must be what
  // was meant, or the command fails before writing anything.
  const tape::Format format = tape_format(o);
  const tape::Program program = make_program(res, o);
  const std::string text = tape::format_program(program, format);
  const std::vector<uint8_t> frames = tape::add_parity(text);
  const tape::Program back = tape::parse_frames(frames, format);
  if (back.blocks.size() != program.blocks.size())
    throw std::logic_error("the tape reader read " + std::to_string(back.blocks.size()) +
                           " blocks back, " + std::to_string(program.blocks.size()) + " written");

  // The feed plan on the board's machine (its 12 MHz clock, the default rapid rate).
  std::optional<checker::FeedPlan> plan;
  if (o.accel_mm_s2 > 0) {
    a.plan.accel_mm_s2 = o.accel_mm_s2;
    const InterpConfig machine = a.board.empty()
                                     ? interp_config(kPlanClockHz, format)
                                     : board::board_interp_config(board::board_named(a.board), kPlanClockHz, 0);
    plan = checker::plan_feed(back, machine, kPlanClockHz, a.plan);
  }

  // Independent measure of the contour path (before the cutter offset) against the contour.
  const auto t_measure = std::chrono::steady_clock::now();
  const DeviationReport dev =
      measure_deviation(contour, res.contour_start, res.contour_moves, o.blu_mm, o.tol_mm / 4);
  const double measure_s = seconds_since(t_measure);

  // Blocks by kind, so the summary adds up: chord blocks of curves, straight blocks
  // (programmed lines, rapids, the offset's joins), quadrant arc blocks.
  long lines = 0, arcs = 0, chords = 0, chord_blocks = 0, traverses = 0;
  for (const Move& m : res.moves) {
    (m.kind == MoveKind::kLine ? lines : arcs) += 1;
    if (m.kind == MoveKind::kLine && m.chord) ++chord_blocks;
    if (m.rapid) ++traverses;
  }
  // Arcs fed below --feed at sqrt(A R) (make_program(), by the radius of the arc's I, J).
  long arcs_slowed = 0;
  for (const tape::Block& b : program.blocks)
    if (tape::is_arc(b.motion) && arc_feed_mm_min(std::hypot(b.i, b.j) * o.blu_mm, o) < o.feed_mm_min) ++arcs_slowed;
  const std::vector<PassFigures> passes = pass_figures(contour, res, o.blu_mm);
  nlohmann::json pass_list = nlohmann::json::array();
  for (const PassFigures& f : passes)
    pass_list.push_back({{"depth_mm", std::isnan(f.depth_mm) ? nlohmann::json() : nlohmann::json(f.depth_mm)},
                         {"blocks", f.blocks},
                         {"traverse_blocks", f.traverse_blocks},
                         {"first_block", f.first_block},
                         {"cut_mm", f.cut_mm},
                         {"traverse_mm", f.traverse_mm}});
  nlohmann::json per_element = nlohmann::json::array();
  for (size_t i = 0; i < res.chords_per_element.size(); ++i) {
    chords += res.chords_per_element[i];
    per_element.push_back({{"element", contour.element_names[i]}, {"chords", res.chords_per_element[i]}});
  }
  const bool is_frames = tape::is_frame_file(a.output);
  nlohmann::json report = {
      {"input", a.input},
      {"input_kind", input_kind_name(input_kind_of(a.input))},
      {"output", a.output},
      {"method", o.method},
      {"tol_mm", o.tol_mm},
      {"blu_mm", o.blu_mm},
      {"width", o.width},
      {"arcs", a.arcs},
      {"zones", o.zones},
      {"budget_blu", o.budget_blu},
      {"cutter_radius_mm", o.cutter_radius_mm},
      {"side", a.side},
      {"feed_mm_min", o.feed_mm_min},
      {"chord_delta_mm", res.chord_delta_mm},
      {"start_mm", mm_point(res.start, o.blu_mm)},
      {"blocks", program.blocks.size()},
      {"line_blocks", lines},
      {"arc_blocks", arcs},
      {"traverse_blocks", traverses},
      {"arcs_slowed_to_accel", arcs_slowed},
      {"passes", pass_list},
      {"chords", chords},
      {"chords_per_element", per_element},
      {"max_deviation_mm", dev.max_mm},
      {"deviation",
       {{"measure", "sampled Hausdorff distance between the contour and its chord/arc path before "
                    "the cutter offset: both sampled every step_mm, each sample measured to the "
                    "polyline through the other's samples; an estimate (it may be off by the "
                    "sagitta of one step, either way), not a bound: `ncinterp check` measures the "
                    "pulse path exactly"},
        {"step_mm", o.tol_mm / 4},
        {"path_to_contour_mm", dev.path_to_contour_mm},
        {"contour_to_path_mm", dev.contour_to_path_mm},
        {"samples", dev.samples}}},
      {"tape",
       {{"frames", frames.size()},
        {"bytes", is_frames ? frames.size() : text.size()},
        {"paper_m", frames.size() * 0.00254}}},  // 10 frames per inch
      {"warnings", [&] {
         nlohmann::json w = nlohmann::json::array();
         for (const std::string& line : contour.warnings) w.push_back(line);
         for (const std::string& line : res.warnings) w.push_back(line);
         return w;
       }()},
      {"planner",
       {{"chords", res.planner.chords},
        {"retries", res.planner.retries},
        {"fallbacks", res.planner.fallbacks}}},
      {"time_s",
       {{"read", std::chrono::duration<double>(t_read - t0).count()},
        {"first_stage", stage_s},
        {"measure", measure_s}}},
  };

  if (plan) report["feed_plan"] = plan_json(*plan, a.plan);

  // What was read back is what is written (write_tape_file would format it again).
  OutputSet::write(tape_out, is_frames ? std::string_view(reinterpret_cast<const char*>(frames.data()),
                                                         frames.size())
                                       : std::string_view(text));
  if (report_out) OutputSet::write(report_out, report.dump(2) + "\n");
  outputs.commit();
  // The summary goes to stderr when the tape itself goes to standard output.
  FILE* summary = a.output == "-" ? stderr : stdout;
  // --tool's blocks without motion: pierce dwells (M03) and still M05 blocks.
  const size_t tool_blocks = program.blocks.size() - res.moves.size();
  std::fprintf(summary,
               "%s: %zu blocks (%ld chords, %ld straight, %ld arc blocks, %ld traverses G00%s), %zu "
               "frames, max deviation %.4f mm sampled every %g mm (tol %g mm; `check` measures "
               "exactly)\n",
               a.output.c_str(), program.blocks.size(), chord_blocks, lines - chord_blocks - traverses,
               arcs, traverses,
               tool_blocks ? (", " + std::to_string(tool_blocks) + " tool blocks without motion").c_str() : "",
               frames.size(), dev.max_mm, o.tol_mm / 4, o.tol_mm);
  if (arcs_slowed > 0)
    std::fprintf(summary, "  %ld arc block(s) fed below --feed, at sqrt(A R): their centripetal acceleration "
                 "within %g mm/s^2\n", arcs_slowed, o.accel_mm_s2);
  if (passes.size() > 1 || !std::isnan(passes.front().depth_mm))
    for (size_t p = 0; p < passes.size(); ++p)
      std::fprintf(summary, "  pass %zu at %s: %ld blocks from N%ld (%ld traverses), %.3f mm cut, %.3f mm traversed\n",
                   p + 1, depth_text(passes[p].depth_mm).c_str(), passes[p].blocks, passes[p].first_block,
                   passes[p].traverse_blocks, passes[p].cut_mm, passes[p].traverse_mm);
  if (plan) {
    std::fprintf(summary, "  cycle time at %g mm/s^2 (%g MHz board): %.2f s at exact stop (as played), %.2f s "
                 "without a ramp; continuous mode (G64, junction deviation %g mm, planned only, not built): ",
                 o.accel_mm_s2, kPlanClockHz / 1e6, plan->exact_stop_s, plan->programmed_s, a.plan.junction_deviation_mm);
    for (size_t i = 0; i < plan->continuous.size(); ++i) {
      const checker::ContinuousPlan& c = plan->continuous[i];
      std::fprintf(summary, "%s%.2f s reading %s", i ? ", " : "", c.seconds,
                   c.lookahead == 0 ? "the whole tape ahead"
                                    : (std::to_string(c.lookahead) + " block" + (c.lookahead > 1 ? "s" : "") + " ahead").c_str());
    }
    std::fprintf(summary, "\n");
  }
  if (!a.report.empty()) std::fprintf(summary, "report: %s\n", a.report.c_str());
  return 0;
}

const CommandRegistration registration("tape", [](CLI::App& app) {
  auto args = std::make_shared<TapeArgs>();
  FirstStageOptions& o = args->options;
  CLI::App* cmd = app.add_subcommand("tape", "First stage: contour -> chords within --tol -> tape");
  cmd->add_option("INPUT", args->input,
                  "contour: .json (segments or reference-point table), .nc/.ngc/.gcode/.tap (G-code), "
                  ".dat (airfoil, Selig or Lednicer)")
      ->required();
  cmd->add_option("-o,--output", args->output, "tape: .tape (frames with parity) or .nc (plain text)")
      ->required();
  cmd->add_option("--tol", o.tol_mm, "delta: how far the pulse path may be from the contour, mm")
      ->capture_default_str();
  cmd->add_option("--method", o.method, "1 trial, 2 one-sided, 3 two-sided chords (Tamm)")
      ->check(CLI::IsMember({1, 2, 3}))
      ->capture_default_str();
  cmd->add_option("--blu", o.blu_mm, "basic length unit, mm (10^-k)")->capture_default_str();
  cmd->add_option("--width", o.width, "increment register width W: |dx|,|dy| <= 2^W - 1 BLU")
      ->capture_default_str();
  cmd->add_option("--arcs", args->arcs, "circular arcs as chords or as quadrant arc blocks")
      ->check(CLI::IsMember({"chords", "circle"}))
      ->capture_default_str();
  cmd->add_option("--cutter-radius", o.cutter_radius_mm, "tape the cutter centre at this radius, mm")
      ->capture_default_str();
  cmd->add_option("--side", args->side, "cutter side of the direction of travel (G41 left, G42 right)")
      ->check(CLI::IsMember({"left", "right"}))
      ->capture_default_str();
  cmd->add_option("--feed", o.feed_mm_min, "feed, mm/min (written as inverse time, G93)")
      ->capture_default_str();
  cmd->add_flag("--zones", o.zones, "end chords at every reference point (joint), as in the paper");
  cmd->add_flag("--tool", o.tool,
                "the tool output on for the cuts only (laser, torch, pen): M03 with the first cut "
                "after each traverse, M05 with the last before the next");
  cmd->add_option("--pierce-delay", o.pierce_delay_s,
                  "with --tool: seconds the tool is on at rest before each run of cuts (a torch's or "
                  "laser's pierce): an M03 block that dwells, then the cuts")
      ->check(CLI::Range(0.001, 3600.0))
      ->needs("--tool");
  cmd->add_option("--accel", o.accel_mm_s2,
                  "the machine's acceleration limit, mm/s^2: arcs are fed at most sqrt(A R) (their "
                  "centripetal acceleration within it), and the feed is planned: the cycle time at "
                  "exact stop (what the machine plays with play/check --accel) and what continuous mode "
                  "(G64, planned only) would take (docs/motion-control.md 7); default with --board: "
                  "the board's own limit (500 on the iCEBreaker)")
      ->check(CLI::PositiveNumber);
  cmd->add_option("--junction-deviation", args->plan.junction_deviation_mm,
                  "continuous mode's corner rule (grbl's, Klipper's), mm: only in --accel's plan")
      ->check(CLI::PositiveNumber)
      ->capture_default_str();
  cmd->add_option("--budget-blu", o.budget_blu, "interpolator's own error reserved from --tol, BLU")
      ->capture_default_str();
  cmd->add_option("--airfoil-chord", args->airfoil_chord_mm, "chord of a .dat airfoil, mm")
      ->capture_default_str();
  cmd->add_option("--cut-z", args->cut_z_mm,
                  "G-code with Z: tape only the pass at this depth, mm; the feed moves at other "
                  "depths become traverses (default: one pass per depth, shallowest first)");
  cmd->add_option("--report", args->report, "write a JSON report");
  cmd->add_option("--board", args->board,
                  "the tape is for this board (icestick: lines only; icebreaker): refused, with the "
                  "reason, when its interpolator cannot play it")
      ->check(CLI::IsMember({"icestick", "icebreaker"}));
  cmd->callback([args] {
    try {
      run(*args);
    } catch (const InputError& e) {
      std::cerr << e.what() << "\n";  // "FILE:LINE: what is wrong"
      throw CommandExit{1};
    } catch (const tape::TapeFormatError& e) {
      std::cerr << "ncinterp tape: internal error: " << args->output << ": "
                << tape::describe(e.info()) << "\n";
      throw CommandExit{1};
    } catch (const std::exception& e) {
      std::cerr << "ncinterp tape: " << e.what() << "\n";
      throw CommandExit{1};
    }
  });
});

}  // namespace
}  // namespace ncinterp::cli
