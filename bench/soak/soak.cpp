// Soak: many random contours through the whole chain (first stage -> tape -> engine ->
// trajectory checker), outside CI. One line per case; a failing case is written to
// --dump DIR (input file, tape, JSON report and the commands that reproduce it).
// Usage (docs/verification.md):  build/bench/soak/ncinterp_soak --cases 500 --seed 1
#include <CLI/CLI.hpp>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>

#include "atomic_file.h"
#include "check_report.h"
#include "random_contour.h"

namespace {

using namespace ncinterp;

struct Args {
  uint64_t cases = 200;
  uint64_t seed = 1;
  std::string engine = "golden";
  double seconds = 0.5;
  std::string dump;
  bool no_arcs = false;
  bool bit_serial = false;
};

std::string tape_command(const regression::Case& c, const std::string& input) {
  const auto& o = c.first_stage;
  char buf[512];
  std::snprintf(buf, sizeof buf,
                "ncinterp tape %s -o %s.tape --tol %g --method %d --blu %g --width %u --arcs %s "
                "--feed %.17g%s",
                input.c_str(), c.name.c_str(), o.tol_mm, o.method, o.blu_mm, o.width,
                o.arcs_circle ? "circle" : "chords", o.feed_mm_min,
                o.cutter_radius_mm > 0
                    ? (" --cutter-radius " + std::to_string(o.cutter_radius_mm) + " --side " +
                       (o.side_left ? "left" : "right"))
                          .c_str()
                    : "");
  return buf;
}

void dump_case(const std::string& dir, const regression::Case& c, const regression::GeneratedInput& in,
               const checker::CheckOutcome* out, const std::string& why) {
  namespace fs = std::filesystem;
  fs::create_directories(dir);
  const std::string base = (fs::path(dir) / c.name).string();
  write_file_atomically(dir + "/" + in.file_name, in.text);
  std::string notes = "# " + why + "\n" + tape_command(c, in.file_name) + "\n";
  if (out) {
    const auto frames = regression::make_tape(c);
    write_file_atomically(base + ".tape", frames);
    checker::ReportContext ctx;
    ctx.tape_file = c.name + ".tape";
    ctx.contour_file = in.file_name;
    ctx.setup = c.check;
    ctx.setup.tol_mm = c.first_stage.tol_mm;
    ctx.setup.cutter_radius_mm = c.first_stage.cutter_radius_mm;
    ctx.setup.cutter_left = c.first_stage.side_left;
    write_file_atomically(base + ".report.json", checker::check_report_json(*out, ctx).dump(1) + "\n");
    const checker::GridPoint s = out->reference ? out->reference->start() : checker::GridPoint{};
    char buf[512];
    std::snprintf(buf, sizeof buf,
                  "ncinterp check %s.tape --contour %s --tol %g --blu %g --width %u --reader-cps %g%s "
                  "--start %.6f,%.6f%s --svg %s.svg --report %s.report.json\n",
                  c.name.c_str(), in.file_name.c_str(), c.first_stage.tol_mm, c.first_stage.blu_mm,
                  c.first_stage.width, c.check.reader_cps, c.check.bit_serial ? " --bit-serial" : "",
                  s.x * out->blu_mm, s.y * out->blu_mm,
                  c.first_stage.cutter_radius_mm > 0
                      ? (" --cutter-radius " + std::to_string(c.first_stage.cutter_radius_mm) +
                         " --side " + (c.first_stage.side_left ? "left" : "right"))
                            .c_str()
                      : "",
                  c.name.c_str(), c.name.c_str());
    notes += buf;
    if (in.kind == regression::ShapeKind::kAirfoil)
      notes += "# airfoil chord: --airfoil-chord " + std::to_string(in.airfoil_chord_mm) + "\n";
  }
  write_file_atomically(base + ".txt", notes);
}

}  // namespace

int main(int argc, char** argv) {
  Args a;
  CLI::App app{"ncinterp soak: random contours through the first stage, the tape, the engines and the checker"};
  app.add_option("--cases", a.cases, "number of random cases")->capture_default_str();
  app.add_option("--seed", a.seed, "seed of the first case (case i uses seed + i)")->capture_default_str();
  app.add_option("--engine", a.engine, "engine(s) to play each tape on")
      ->check(CLI::IsMember({"golden", "rtl", "both"}))
      ->capture_default_str();
  app.add_option("--seconds", a.seconds, "machine time of each contour (sets the feed)")->capture_default_str();
  app.add_option("--dump", a.dump, "directory for failing cases (input, tape, report, commands)");
  app.add_flag("--bit-serial", a.bit_serial,
               "play as the board does: the DDA (player and dry run) and the digits bit-serial (golden engine only)");
  app.add_flag("--no-arcs", a.no_arcs, "never cut arcs as G02/G03 blocks (--arcs circle); by default half the contours with arcs are");
  CLI11_PARSE(app, argc, argv);
  if (a.bit_serial && a.engine != "golden") {
    std::fprintf(stderr, "ncinterp_soak: --bit-serial needs --engine golden (the verilated RTL "
                         "has the parallel dry run)\n");
    return 1;
  }

  std::vector<EngineKind> engines;
  if (a.engine != "rtl") engines.push_back(EngineKind::kGolden);
  if (a.engine != "golden") engines.push_back(EngineKind::kRtl);
  regression::RandomCaseLimits limits;
  limits.seconds = a.seconds;
  limits.arcs_circle_allowed = !a.no_arcs;

  const auto t0 = std::chrono::steady_clock::now();
  uint64_t failures = 0, clocks = 0, runs = 0, skipped = 0;
  double worst_ratio = 0.0;
  std::string worst_case;
  for (uint64_t i = 0; i < a.cases; ++i) {
    const uint64_t seed = a.seed + i;
    regression::GeneratedInput input;
    regression::Case c;
    try {
      c = regression::random_case(seed, limits, &input);
    } catch (const std::exception& e) {
      ++failures;
      std::printf("%llu: FAIL generating the case: %s\n", static_cast<unsigned long long>(seed), e.what());
      continue;
    }
    c.check.bit_serial = a.bit_serial;
    for (EngineKind engine : engines) {
      c.check.engine = engine;
      if (engine == EngineKind::kRtl &&
          (c.first_stage.width != 16 || c.first_stage.blu_mm != 0.001)) {
        // The verilated RTL has the default parameters only (W 16, 3 fraction digits).
        ++skipped;
        std::printf("%s rtl: not run (RTL built for W 16, BLU 0.001)\n", c.name.c_str());
        continue;
      }
      std::string line;
      try {
        const checker::CheckOutcome out = regression::run_case(c);
        ++runs;
        clocks += out.checker->cycles();
        const double ratio = out.checker->total_error().max * out.blu_mm / c.first_stage.tol_mm;
        if (ratio > worst_ratio) worst_ratio = ratio, worst_case = c.name;
        char buf[256];
        std::snprintf(buf, sizeof buf, "%s %s m%d tol %g R %g W %u: total %.4f mm (%.0f%% of tol), path %.3f BLU, %llu clocks",
                      c.name.c_str(), engine_name(engine), c.first_stage.method,
                      c.first_stage.tol_mm, c.first_stage.cutter_radius_mm, c.first_stage.width,
                      out.checker->total_error().max * out.blu_mm, 100 * ratio, out.checker->path_error().max,
                      static_cast<unsigned long long>(out.checker->cycles()));
        line = buf;
        if (!out.passed()) {
          ++failures;
          std::printf("%s\n%s", line.c_str(), regression::describe(c, out).c_str());
          if (!a.dump.empty()) dump_case(a.dump, c, input, &out, "check failed");
        } else {
          std::printf("%s: ok\n", line.c_str());
        }
      } catch (const std::exception& e) {
        ++failures;
        std::printf("%s %s: FAIL: %s\n", c.name.c_str(), engine_name(engine), e.what());
        if (!a.dump.empty()) dump_case(a.dump, c, input, nullptr, e.what());
      }
      std::fflush(stdout);
    }
  }
  const double secs = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  std::printf("soak: %llu cases, %llu runs (%llu RTL runs not possible), %llu failed; worst total error %.0f%% of tol (%s); %.3g clocks in %.1f s\n",
              static_cast<unsigned long long>(a.cases), static_cast<unsigned long long>(runs),
              static_cast<unsigned long long>(skipped),
              static_cast<unsigned long long>(failures), 100 * worst_ratio, worst_case.c_str(),
              static_cast<double>(clocks), secs);
  return failures ? 1 : 0;
}
