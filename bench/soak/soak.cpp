// Soak: many random contours through the whole chain, outside CI, in every arch: the first
// stage makes the tape; the golden model plays it under the trajectory checker (every
// pulse judged against the tape and the contour); the verilated RTL plays it in lock step
// with the golden model (every output compared on every clock). One line per run; a
// failing case is written to --dump DIR (input file, tape, JSON report and the commands
// that reproduce it). A summary line per arch ends the output.
// Idea: the checker proves the golden model's path right, the lock step proves the RTL
// equal to the golden model clock by clock, so together they prove the RTL's path right.
// The RTL of this build has the default widths (W 16, BLU 0.001 mm); a case drawn with
// other ones plays on an RTL variant verilated for its width, BLU and arch
// (sw/tools/sweep/rtl_variant.h), built on demand and cached under --cache: no RTL run is
// skipped. Those cases' tapes are collected and each variant plays its batch at the end.
// --operator draws an operator per case (operator_events()): the ramp or none, feed holds
// and starts, overrides with the ramp, in one case of four an E-stop or a limit, and in
// every other case a tape with M03 and M05 around its cuts (ncinterp tape --tool); the checker
// and the lock step on the build's RTL play them (a variant's batch plays its tapes without
// them).
// Usage (docs/verification.md):  build/bench/soak/ncinterp_soak --cases 500 --seed 1
#include <CLI/CLI.hpp>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <map>
#include <random>
#include <sstream>

#include "atomic_file.h"
#include "check_report.h"
#include "frame_source.h"
#include "lockstep.h"
#include "random_contour.h"
#include "rtl_models.h"
#include "rtl_variant.h"
#include "sweep_defaults.h"

namespace {

using namespace ncinterp;
namespace fs = std::filesystem;

struct Args {
  uint64_t cases = 200;
  uint64_t seed = 1;
  std::string engine = "both";
  std::vector<std::string> archs = {"serial", "parallel"};
  double seconds = 0.5;
  std::string dump;
  std::string cache;
  bool no_arcs = false;
  bool lines_only = false;
  bool operator_events = false;
};

// Per arch: runs, failures, clocks, wall time.
struct ArchTally {
  uint64_t golden_runs = 0, rtl_runs = 0, variant_runs = 0, failures = 0, clocks = 0;
  double seconds = 0;
};

std::string tape_command(const regression::Case& c, const std::string& input) {
  const auto& o = c.first_stage;
  char buf[2048];
  std::snprintf(buf, sizeof buf,
                "ncinterp tape %s -o %s.tape --tol %g --method %d --blu %g --width %u --arcs %s "
                "--feed %.17g%s%s%s",
                input.c_str(), c.name.c_str(), o.tol_mm, o.method, o.blu_mm, o.width,
                o.arcs_circle ? "circle" : "chords", o.feed_mm_min, o.tool ? " --tool" : "",
                o.accel_mm_s2 > 0 ? (" --accel " + std::to_string(o.accel_mm_s2)).c_str() : "",
                o.cutter_radius_mm > 0
                    ? (" --cutter-radius " + std::to_string(o.cutter_radius_mm) + " --side " +
                       (o.side_left ? "left" : "right"))
                          .c_str()
                    : "");
  return buf;
}

// The case's input, tape and notes (why, and the commands that reproduce it: the tape, and
// the check or the cosim) into dir; the checker's report when there is one.
void dump_case(const std::string& dir, const regression::Case& c, const regression::GeneratedInput& in,
               const checker::CheckOutcome* out, const std::string& why) {
  fs::create_directories(dir);
  const std::string base = (fs::path(dir) / c.name).string();
  write_file_atomically(dir + "/" + in.file_name, in.text);
  write_file_atomically(base + ".tape", regression::make_tape(c));
  const char* arch = arch_name(c.check.arch);
  std::string notes = "# " + why + "\n" + tape_command(c, in.file_name) + "\n";
  // The operator (--operator), as both commands read it.
  std::string machine = " --clock-hz " + std::to_string(c.check.clock_hz);
  if (c.check.accel_mm_s2 > 0) machine += " --accel " + std::to_string(c.check.accel_mm_s2);
  if (!c.check.events.empty()) machine += " --events " + events_text(c.check.events, c.check.clock_hz);
  char buf[2048];
  std::snprintf(buf, sizeof buf, "ncinterp cosim %s.tape --arch %s --reader-cps %g%s  # W %u, BLU %g: the "
                "RTL of `ncinterp` has W 16, BLU 0.001; others play on ncinterp_rtl_variant\n",
                c.name.c_str(), arch, c.check.reader_cps, machine.c_str(), c.first_stage.width, c.first_stage.blu_mm);
  notes += buf;
  if (out) {
    checker::ReportContext ctx;
    ctx.tape_file = c.name + ".tape";
    ctx.contour_file = in.file_name;
    ctx.setup = c.check;
    ctx.setup.tol_mm = c.first_stage.tol_mm;
    ctx.setup.cutter_radius_mm = c.first_stage.cutter_radius_mm;
    ctx.setup.cutter_left = c.first_stage.side_left;
    write_file_atomically(base + ".report.json", checker::check_report_json(*out, ctx).dump(1) + "\n");
    const checker::GridPoint s = out->reference ? out->reference->start() : checker::GridPoint{};
    std::snprintf(buf, sizeof buf,
                  "ncinterp check %s.tape --contour %s --arch %s --tol %g --blu %g --width %u --reader-cps %g%s "
                  "--start %.6f,%.6f%s --svg %s.svg --report %s.report.json\n",
                  c.name.c_str(), in.file_name.c_str(), arch, c.first_stage.tol_mm, c.first_stage.blu_mm,
                  c.first_stage.width, c.check.reader_cps, machine.c_str(), s.x * out->blu_mm, s.y * out->blu_mm,
                  c.first_stage.cutter_radius_mm > 0
                      ? (" --cutter-radius " + std::to_string(c.first_stage.cutter_radius_mm) +
                         " --side " + (c.first_stage.side_left ? "left" : "right"))
                            .c_str()
                      : "",
                  c.name.c_str(), c.name.c_str());
    notes += buf;
  }
  if (in.kind == regression::ShapeKind::kAirfoil)
    notes += "# airfoil chord: --airfoil-chord " + std::to_string(in.airfoil_chord_mm) + "\n";
  write_file_atomically(base + ".txt", notes);
}

// The configuration the RTL of a case plays with (its tape's format, its arch, its ramp).
InterpConfig case_config(const regression::Case& c) {
  checker::CheckSetup s = c.check;
  checker::match_first_stage(s, c.first_stage, {});
  InterpConfig cfg = interp_config(s.clock_hz, s.format, s.rapid_mm_min, s.accel_mm_s2);
  cfg.arch = c.check.arch;
  return cfg;
}

// A random operator for a case of about `seconds` of machine time (--operator): the ramp at
// 500 mm/s^2 in half the cases, up to three feed holds each with its start a little later,
// with the ramp up to three feed overrides (25 % to 200 %) and a rapid override, and in one
// case of four an E-stop or a limit somewhere in the run (or after it).
void operator_events(checker::CheckSetup& s, uint64_t seed, double seconds) {
  std::mt19937_64 rng(seed * 7919 + 17);
  const auto clock = [&](double from_s, double to_s) {
    return static_cast<uint64_t>(std::uniform_real_distribution<double>(from_s, to_s)(rng) * s.clock_hz) + 1;
  };
  s.accel_mm_s2 = rng() % 2 ? 500.0 : 0.0;
  s.events.clear();
  for (int k = static_cast<int>(rng() % 4); k > 0; --k) {
    const uint64_t hold = clock(0, 1.2 * seconds);
    s.events.push_back({hold, OperatorEvent::kHold});
    s.events.push_back({hold + clock(0.001, 0.1), OperatorEvent::kStart});
  }
  if (s.accel_mm_s2 > 0) {
    for (int k = static_cast<int>(rng() % 4); k > 0; --k)
      s.events.push_back({clock(0, seconds), OperatorEvent::kFeedOverride,
                          static_cast<uint16_t>(kOverrideOne / 4 + rng() % (7 * kOverrideOne / 4 + 1))});
    const uint16_t rapid[] = {kOverrideOne / 4, kOverrideOne / 2, kOverrideOne};
    if (rng() % 2) s.events.push_back({clock(0, seconds), OperatorEvent::kRapidOverride, rapid[rng() % 3]});
  }
  if (rng() % 4 == 0) {
    const OperatorEvent::Kind stops[] = {OperatorEvent::kEStop, OperatorEvent::kLimitX, OperatorEvent::kLimitY};
    s.events.push_back({clock(0, 1.5 * seconds), stops[rng() % 3]});
  }
  sort_by_clock(s.events);
}

// A case waiting for its RTL variant's batch.
struct Queued {
  regression::Case c;
  regression::GeneratedInput input;
  std::string tape;
};

}  // namespace

int main(int argc, char** argv) {
  Args a;
  CLI::App app{"ncinterp soak: random contours through the first stage, the tape, the golden model "
               "under the checker and the RTL in lock step, in every arch"};
  app.add_option("--cases", a.cases, "number of random cases")->capture_default_str();
  app.add_option("--seed", a.seed, "seed of the first case (case i uses seed + i)")->capture_default_str();
  app.add_option("--engine", a.engine,
                 "golden: the checker on the golden model; rtl: the RTL in lock step with it; both")
      ->check(CLI::IsMember({"golden", "rtl", "both"}))
      ->capture_default_str();
  app.add_option("--archs", a.archs, "microarchitectures to play every case on")
      ->delimiter(',')
      ->check(CLI::IsMember({"serial", "parallel"}))
      ->capture_default_str();
  app.add_option("--seconds", a.seconds, "machine time of each contour (sets the feed)")->capture_default_str();
  app.add_option("--dump", a.dump, "directory for failing cases (input, tape, report, commands)");
  app.add_option("--cache", a.cache,
                 "RTL variants' build trees and tapes (default: <build>/soak-cache)");
  app.add_flag("--no-arcs", a.no_arcs, "never cut arcs as G02/G03 blocks (--arcs circle); by default half the contours with arcs are");
  app.add_flag("--lines-only", a.lines_only,
               "the interpolator without circle mode (CircleMode = 0, the iCEstick's core): chords only, "
               "the golden model and the RTL built so");
  app.add_flag("--operator", a.operator_events,
               "draw an operator per case: the ramp at 500 mm/s^2 or none, feed holds and starts, overrides "
               "with the ramp, in one case of four an E-stop or a limit (a variant's RTL batch plays "
               "without them)");
  CLI11_PARSE(app, argc, argv);

  const bool golden = a.engine != "rtl", rtl = a.engine != "golden";
  std::vector<Arch> archs;
  for (const std::string& name : a.archs) archs.push_back(parse_arch(name));
  const std::string cache = a.cache.empty() ? fs::path(sweep::default_cache_dir()).parent_path().string() + "/soak-cache"
                                            : a.cache;
  sweep::RtlVariantSetup variants = sweep::default_rtl_variant_setup(cache);
  regression::RandomCaseLimits limits;
  limits.seconds = a.seconds;
  limits.arcs_circle_allowed = !a.no_arcs && !a.lines_only;

  const auto t0 = std::chrono::steady_clock::now();
  std::map<Arch, ArchTally> tally;
  uint64_t generation_failures = 0;
  double worst_ratio = 0.0;
  std::string worst_case;
  // Cases whose RTL is a variant, by variant.
  std::map<std::string, std::pair<sweep::RtlVariant, std::vector<Queued>>> queued;
  auto fail = [&](const regression::Case& c, const regression::GeneratedInput& in, const checker::CheckOutcome* out,
                  const std::string& why) {
    ++tally[c.check.arch].failures;
    if (!a.dump.empty()) dump_case(a.dump + "/" + arch_name(c.check.arch), c, in, out, why);
  };

  for (uint64_t i = 0; i < a.cases; ++i) {
    const uint64_t seed = a.seed + i;
    regression::GeneratedInput input;
    regression::Case c;
    try {
      c = regression::random_case(seed, limits, &input);
    } catch (const std::exception& e) {
      ++generation_failures;
      std::printf("%llu: FAIL generating the case: %s\n", static_cast<unsigned long long>(seed), e.what());
      continue;
    }
    c.check.format.circle_mode = !a.lines_only;
    if (a.operator_events) {
      operator_events(c.check, seed, a.seconds);
      c.first_stage.tool = seed % 2 == 0;  // M03 and M05 around the cuts (the tool rule)
      // Taped for the machine's limit, as `tape --accel` does: arcs within sqrt(A R).
      c.first_stage.accel_mm_s2 = c.check.accel_mm_s2;
    }
    for (Arch arch : archs) {
      c.check.arch = arch;
      ArchTally& t = tally[arch];
      const auto a0 = std::chrono::steady_clock::now();
      const char* name = arch_name(arch);
      uint64_t golden_clocks = 0;
      if (golden) {
        c.check.engine = EngineKind::kGolden;
        try {
          const checker::CheckOutcome out = regression::run_case(c);
          ++t.golden_runs;
          golden_clocks = out.checker->cycles();
          t.clocks += golden_clocks;
          const double ratio = out.checker->total_error().max * out.blu_mm / c.first_stage.tol_mm;
          if (ratio > worst_ratio) worst_ratio = ratio, worst_case = c.name;
          std::printf("%s %s golden m%d tol %g R %g W %u BLU %g: total %.4f mm (%.0f%% of tol), path %.3f BLU, "
                      "%llu clocks%s: %s\n",
                      c.name.c_str(), name, c.first_stage.method, c.first_stage.tol_mm,
                      c.first_stage.cutter_radius_mm, c.first_stage.width, c.first_stage.blu_mm,
                      out.checker->total_error().max * out.blu_mm, 100 * ratio, out.checker->path_error().max,
                      static_cast<unsigned long long>(golden_clocks),
                      c.check.events.empty() && c.check.accel_mm_s2 == 0 ? ""
                      : out.checker->stopped()                          ? " (operator; stopped)"
                                                                        : " (operator)",
                      out.passed() ? "ok" : "FAIL");
          if (!out.passed()) {
            std::printf("%s", regression::describe(c, out).c_str());
            fail(c, input, &out, "check failed on the golden model");
          }
        } catch (const std::exception& e) {
          std::printf("%s %s golden: FAIL: %s\n", c.name.c_str(), name, e.what());
          fail(c, input, nullptr, e.what());
        }
      }
      if (rtl) {
        const InterpConfig cfg = case_config(c);
        if (cfg.same_parameters(rtl_built_config(arch))) {
          try {
            cosim::Options o;
            o.config = cfg;
            o.events = c.check.events;
            o.cycles_per_frame = FrameSource::cycles_per_frame_for(c.check.clock_hz, c.check.reader_cps);
            if (golden_clocks) o.max_cycles = 2 * golden_clocks + 1'000'000;
            const cosim::Result r = cosim::run_lockstep(regression::make_tape(c), o);
            ++t.rtl_runs;
            t.clocks += r.cycles;
            const bool stopped = r.end == cosim::Result::End::kTapeError && is_stop_error(r.last.error_code) &&
                                 first_stop(o.events);
            if (r.end == cosim::Result::End::kDone || stopped) {
              std::printf("%s %s rtl: lock step ok, %llu clocks%s\n", c.name.c_str(), name,
                          static_cast<unsigned long long>(r.cycles), stopped ? ", stopped" : "");
            } else {
              const std::string why = r.mismatch ? "RTL differs at " + cosim::describe(*r.mismatch)
                                                 : std::string("the lock step did not reach done");
              std::printf("%s %s rtl: FAIL: %s\n", c.name.c_str(), name, why.c_str());
              fail(c, input, nullptr, why);
            }
          } catch (const std::exception& e) {
            std::printf("%s %s rtl: FAIL: %s\n", c.name.c_str(), name, e.what());
            fail(c, input, nullptr, e.what());
          }
        } else {
          const sweep::RtlVariant v{cfg.inc_width, cfg.frac_digits, arch, cfg.circle_mode};
          auto& [variant, batch] = queued[v.name()];
          variant = v;
          const fs::path dir = fs::path(cache) / "tapes" / v.key();
          fs::create_directories(dir);
          const std::string tape = (dir / (c.name + ".tape")).string();
          write_file_atomically(tape, regression::make_tape(c));
          batch.push_back({c, input, tape});
        }
      }
      t.seconds += std::chrono::duration<double>(std::chrono::steady_clock::now() - a0).count();
      std::fflush(stdout);
    }
  }

  // The variants' batches: each variant is built (if its tree is not up to date) and plays
  // its tapes in lock step; every tape must end "done".
  for (auto& [key, entry] : queued) {
    auto& [v, batch] = entry;
    const auto a0 = std::chrono::steady_clock::now();
    ArchTally& t = tally[v.arch];
    std::vector<std::string> tapes, lines;
    for (const Queued& q : batch) tapes.push_back(q.tape);
    variants.reader_cps = batch.front().c.check.reader_cps;
    variants.clock_hz = batch.front().c.check.clock_hz;
    const sweep::RtlResult r = sweep::run_rtl_variant(variants, v, tapes, &lines);
    // "END CYCLES TAPE" or "END CYCLES TAPE: why" (the tape paths have no spaces).
    std::map<std::string, std::string> line_of;  // tape -> its line
    for (const std::string& line : lines) {
      std::istringstream in(line);
      std::string end, cycles, tape;
      in >> end >> cycles >> tape;
      if (!tape.empty() && tape.back() == ':') tape.pop_back();
      line_of[tape] = line;
    }
    for (const Queued& q : batch) {
      ++t.variant_runs;
      const auto it = line_of.find(q.tape);
      const std::string line = it == line_of.end() ? "" : it->second;
      if (line.rfind("done ", 0) == 0) {
        t.clocks += std::stoull(line.substr(5));
        std::printf("%s %s rtl (%s variant): lock step ok, %s\n", q.c.name.c_str(), arch_name(v.arch),
                    v.name().c_str(), line.c_str());
      } else {
        const std::string why = line.empty() ? r.summary : line;
        std::printf("%s %s rtl (%s variant): FAIL: %s\n", q.c.name.c_str(), arch_name(v.arch), v.name().c_str(),
                    why.c_str());
        fail(q.c, q.input, nullptr, why);
      }
    }
    t.seconds += std::chrono::duration<double>(std::chrono::steady_clock::now() - a0).count();
    std::fflush(stdout);
  }

  const double secs = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  uint64_t failures = generation_failures;
  for (const auto& [arch, t] : tally) {
    failures += t.failures;
    std::printf("soak %s: %llu cases, %llu golden runs under the checker, %llu RTL lock steps (%llu on "
                "variants), %llu failed; %.3g clocks in %.1f s\n",
                arch_name(arch), static_cast<unsigned long long>(a.cases),
                static_cast<unsigned long long>(t.golden_runs),
                static_cast<unsigned long long>(t.rtl_runs + t.variant_runs),
                static_cast<unsigned long long>(t.variant_runs), static_cast<unsigned long long>(t.failures),
                static_cast<double>(t.clocks), t.seconds);
  }
  std::printf("soak: %llu cases (seeds %llu..%llu), %llu failed; worst total error %.0f%% of tol (%s); %.1f s\n",
              static_cast<unsigned long long>(a.cases), static_cast<unsigned long long>(a.seed),
              static_cast<unsigned long long>(a.seed + a.cases - 1), static_cast<unsigned long long>(failures),
              100 * worst_ratio, worst_case.c_str(), secs);
  return failures ? 1 : 0;
}
