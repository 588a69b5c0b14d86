// circle_bench: the measurements of docs/circle-dda.md, printed as Markdown tables under
// the command that produced them.
// Sections:
//   scheme      forward Euler vs immediate update, free-running, 1 and 10 turns
//   quadrants   the golden circle DDA on full quadrant blocks, worst radial error by radius
//   random      random quadrant arcs: radial error bound, iteration count
//   exhaustive  every good arc of small machines (W = 5, 6)
//   feed        arc blocks played by the whole golden interpolator: block time against
//               1/F, saturation, the decoder's arc preparation against the block time
// Idea: all numbers come from the same golden classes the interpolator uses
// (sc_model/golden/dda_circle.h, arc_geometry.h, interp_top.h), except the scheme
// study, which needs a free-running circle (sw/tools/circle_study/scheme_study.h).
#include <CLI/CLI.hpp>
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <random>
#include <string>
#include <vector>

#include "arc_geometry.h"
#include "arc_cases.h"
#include "firststage.h"
#include "frame_source.h"
#include "interp_top.h"
#include "scheme_study.h"
#include "tape.h"

namespace ncinterp::bench {
namespace {

using circle_study::QuadrantArc;
using circle_study::Scheme;
using circle_study::TurnStats;
using circle_study::run_free_turns;
using circle_study::scheme_name;

void scheme_section() {
  std::printf("\n### Update scheme, free-running circle (no counters), counter-clockwise\n\n");
  std::printf("| radius | scheme | max radial error, turn 1 | turn 10 | radius after 10 turns - R |"
              " iterations per turn |\n|---:|---|---:|---:|---:|---:|\n");
  for (int64_t r : {10, 100, 1000, 50000, 65535}) {
    for (Scheme s : {Scheme::kSimultaneous, Scheme::kXFirst, Scheme::kAlternating}) {
      TurnStats turns[10];
      run_free_turns(s, r, 10, turns);
      const double end_r = std::hypot(double(turns[9].end_x), double(turns[9].end_y));
      std::printf("| %lld | %s | %.3f | %.3f | %+.3f | %llu |\n", static_cast<long long>(r),
                  scheme_name(s), turns[0].max_radial_error, turns[9].max_radial_error,
                  end_r - double(r), static_cast<unsigned long long>(turns[0].iterations));
    }
  }
}

struct Worst {
  double error = -1;
  QuadrantArc arc;
  void offer(double e, const QuadrantArc& a) {
    if (e > error) error = e, arc = a;
  }
};

void quadrants_section() {
  std::printf("\n### Full quadrant blocks (golden circle DDA), both directions, all quadrants\n\n");
  const int64_t classes[] = {1, 4, 16, 256, 4096, 32768, 65536};
  std::printf("| radius | radii run | worst radial error | at | max N / 2^k |\n"
              "|---|---:|---:|---|---:|\n");
  std::mt19937_64 rng(7);
  for (int c = 0; c + 1 < 7; ++c) {
    const int64_t lo = classes[c], hi = classes[c + 1] - 1;
    std::vector<int64_t> radii;
    if (hi - lo < 4096) {
      for (int64_t r = lo; r <= hi; ++r) radii.push_back(r);
    } else {
      for (int i = 0; i < 400; ++i) radii.push_back(lo + int64_t(rng() % uint64_t(hi - lo + 1)));
      radii.push_back(hi);
    }
    Worst worst;
    double max_n = 0;
    for (int64_t r : radii)
      for (int q = 0; q < 4; ++q)
        for (bool ccw : {false, true}) {
          const QuadrantArc a = circle_study::full_quadrant(r, q, ccw);
          const circle_study::ArcRunStats s = circle_study::run_arc(a, 16, 1u << 20);
          worst.offer(s.max_radial_error, a);
          max_n = std::max(max_n, double(s.iterations) / double(uint64_t{1} << s.k));
        }
    std::printf("| %lld .. %lld | %zu | %.3f | %s | %.3f |\n", static_cast<long long>(lo),
                static_cast<long long>(hi), radii.size(), worst.error, worst.arc.describe().c_str(),
                max_n);
  }
}

void random_section(int count, uint64_t seed) {
  std::printf("\n### %d random quadrant arcs, W = 16 (radius log-uniform 1 .. 65535)\n\n", count);
  std::mt19937_64 rng(seed);
  Worst abs_err, excess, excess_off, spiral, spiral_excess;
  const double classes[] = {1, 16, 256, 4096, 65536};
  Worst by_class[4];  // max (error - |R1 - R0|) by start radius
  double max_n = 0, max_off = 0;
  uint64_t off_arcs = 0;
  for (int t = 0; t < count; ++t) {
    QuadrantArc a = circle_study::random_arc(rng, 65535);
    // Every other arc: move the end by up to 1 BLU per coordinate while it stays good, to
    // reach ends a whole BLU off the circle.
    const bool perturbed = t % 2 == 1;
    if (perturbed) {
      QuadrantArc b = a;
      b.x1 += int64_t(rng() % 3) - 1;
      b.y1 += int64_t(rng() % 3) - 1;
      if (check_arc(b.words(), 16) == TapeError::kNone) a = b;
    }
    const circle_study::ArcRunStats s = circle_study::run_arc(a, 16, 1u << 20);
    const double off = std::fabs(a.end_radius() - a.start_radius());
    abs_err.offer(s.max_radial_error, a);
    spiral.offer(s.max_spiral_error, a);
    spiral_excess.offer(s.max_spiral_error - off, a);
    (perturbed ? excess_off : excess).offer(s.max_radial_error - off, a);
    max_off = std::max(max_off, off);
    for (int c = 0; c < 4; ++c)
      if (a.start_radius() >= classes[c] && a.start_radius() < classes[c + 1])
        by_class[c].offer(s.max_radial_error - off, a);
    off_arcs += perturbed;
    max_n = std::max(max_n, double(s.iterations) / double(uint64_t{1} << s.k));
  }
  std::printf("| measure | value | worst arc |\n|---|---:|---|\n");
  std::printf("| max radial error (vs start radius R0) | %.3f | %s |\n", abs_err.error,
              abs_err.arc.describe().c_str());
  std::printf("| max (error - \\|R1 - R0\\|), ends rounded from the circle | %.3f | %s |\n",
              excess.error, excess.arc.describe().c_str());
  std::printf("| max (error - \\|R1 - R0\\|), ends moved up to 1 BLU (%llu arcs) | %.3f | %s |\n",
              static_cast<unsigned long long>(off_arcs), excess_off.error,
              excess_off.arc.describe().c_str());
  std::printf("| max error vs r(phi) linear from R0 to R1 (checker's measure) | %.3f | %s |\n",
              spiral.error, spiral.arc.describe().c_str());
  std::printf("| max (error vs r(phi) - \\|R1 - R0\\|) | %.3f | %s |\n", spiral_excess.error,
              spiral_excess.arc.describe().c_str());
  std::printf("| largest \\|R1 - R0\\| | %.3f | |\n", max_off);
  std::printf("| max N / 2^k | %.3f | |\n", max_n);
  std::printf("\n| start radius R0 | max (error - \\|R1 - R0\\|) | at |\n|---|---:|---|\n");
  for (int c = 0; c < 4; ++c)
    std::printf("| %g .. %g | %.3f | %s |\n", classes[c], classes[c + 1], by_class[c].error,
                by_class[c].arc.describe().c_str());
}

// Every good arc with start and end magnitudes < 2^w, both directions.
void exhaustive_width(unsigned w) {
  const int64_t lim = (int64_t{1} << w) - 1;
  Worst excess, abs_err, spiral_excess;
  double max_n = 0;
  uint64_t arcs = 0, failures = 0;
  for (int64_t x0 = -lim; x0 <= lim; ++x0)
    for (int64_t y0 = -lim; y0 <= lim; ++y0) {
      const double r0 = std::hypot(double(x0), double(y0));
      for (int64_t x1 = -lim; x1 <= lim; ++x1) {
        // y1^2 within [(r0 - 1)^2 - x1^2, (r0 + 1)^2 - x1^2], widened by one; check_arc decides.
        const double lo2 = std::max(0.0, (r0 - 1) * (r0 - 1) - double(x1 * x1));
        const double hi2 = (r0 + 1) * (r0 + 1) - double(x1 * x1);
        if (hi2 < 0) continue;
        const int64_t ylo = std::max<int64_t>(0, int64_t(std::sqrt(lo2)) - 1);
        const int64_t yhi = std::min<int64_t>(lim, int64_t(std::sqrt(hi2)) + 1);
        for (int64_t ym = ylo; ym <= yhi; ++ym)
          for (int64_t y1 : {ym, -ym}) {
            if (y1 == 0 && ym != y1) continue;
            for (bool ccw : {false, true}) {
              QuadrantArc a;
              a.x0 = x0, a.y0 = y0, a.x1 = x1, a.y1 = y1, a.ccw = ccw;
              if (check_arc(a.words(), w) != TapeError::kNone) continue;
              ++arcs;
              const circle_study::ArcRunStats s = circle_study::run_arc(a, w, uint64_t{1} << (w + 3));
              if (!s.finished || s.x != x1 || s.y != y1) ++failures;
              abs_err.offer(s.max_radial_error, a);
              const double off = std::fabs(a.end_radius() - a.start_radius());
              excess.offer(s.max_radial_error - off, a);
              spiral_excess.offer(s.max_spiral_error - off, a);
              max_n = std::max(max_n, double(s.iterations) / double(uint64_t{1} << s.k));
            }
          }
      }
    }
  std::printf("| %u | %llu | %llu | %.3f | %.3f | %s | %.3f | %.3f |\n", w,
              static_cast<unsigned long long>(arcs), static_cast<unsigned long long>(failures),
              abs_err.error, excess.error, excess.arc.describe().c_str(), spiral_excess.error,
              max_n);
}

void exhaustive_section(unsigned max_width) {
  std::printf("\n### Every good arc of a W-bit machine, both directions\n\n");
  std::printf("| W | good arcs | wrong end or unfinished | max radial error (vs R0) | max (error - "
              "\\|R1 - R0\\|) | at | max (error vs r(phi) - \\|R1 - R0\\|) | max N / 2^k |\n"
              "|---:|---:|---:|---:|---:|---|---:|---:|\n");
  for (unsigned w = 2; w <= max_width; ++w) exhaustive_width(w);
}

// One full circle of four quadrant blocks of radius r BLU at a contour feed of v mm/min, F
// written as the first stage writes it (rounded down: a block is never faster than the
// feed), played on the golden interpolator at 1 MHz with a reader fast enough never to be
// the bottleneck (one frame per clock), so only the interpolator's own timing shows.
struct FeedRun {
  uint64_t iterations = 0;       // N of the first quadrant
  uint64_t clocks = 0;           // busy clocks of the first quadrant
  double ideal_clocks = 0;       // its length / v, in clocks
  uint64_t feed = 0;             // F on tape, 10^-3 1/min
  bool saturated = false;
  uint64_t gap_clocks = 0;       // clocks between the first load and the end with busy low
};

FeedRun run_feed(int64_t r, double v_mm_min) {
  constexpr double kClockHz = 1e6, kBlu = 0.001;
  InterpConfig cfg;
  cfg.feed_modulus = InterpConfig::feed_modulus_for(kClockHz, cfg.feed_frac_digits);
  const double length_mm = M_PI / 2 * double(r) * kBlu;
  tape::Program p;
  for (int q = 0; q < 4; ++q) {
    const QuadrantArc a = circle_study::full_quadrant(r, q, true);
    tape::Block b;
    b.n = static_cast<uint32_t>(q + 1);
    b.motion = tape::Motion::kArcCcw;
    b.i = -a.x0, b.j = -a.y0, b.dx = a.x1 - a.x0, b.dy = a.y1 - a.y0;
    b.feed = firststage::inverse_time_feed(length_mm, v_mm_min, tape::Format{});
    p.blocks.push_back(b);
  }
  tape::Format format;
  GoldenInterp dut(cfg);
  FrameSource source(tape::add_parity(tape::format_program(p, format)), 1);
  FeedRun run;
  run.feed = p.blocks[0].feed;
  run.ideal_clocks = length_mm / v_mm_min * 60.0 * kClockHz;
  bool started = false;
  while (!dut.outputs().done && !dut.outputs().error) {
    const bool ready = dut.outputs().frame_ready;
    dut.tick(source.inputs());
    source.clock(ready);
    const InterpOutputs& o = dut.outputs();
    started = started || o.busy;
    if (o.busy && o.block_n == 1) {
      ++run.clocks;
      run.saturated = o.feed_saturated;
    }
    if (started && !o.busy && !o.done) ++run.gap_clocks;
  }
  if (dut.outputs().error) throw std::runtime_error("feed run: the tape was refused");
  --run.gap_clocks;  // the clock after the last block, before done rises, is not a gap
  run.iterations = circle_study::run_arc(circle_study::full_quadrant(r, 0, true), 16, 1u << 20).iterations;
  return run;
}

void feed_section() {
  std::printf("\n### Arc blocks on the golden interpolator: time against 1/F (1 MHz, BLU 0.001 mm, "
              "W = 16, full quadrants, four per circle)\n\n");
  std::printf("| radius (BLU) | N | contour feed (mm/min) | F on tape (1/min) | clocks | "
              "length / feed (clocks) | time error | saturated | arc preparation (clocks) | "
              "gap clocks in the circle | feed at saturation (mm/min) |\n"
              "|---:|---:|---:|---:|---:|---:|---:|---|---:|---:|---:|\n");
  for (int64_t r : {1, 10, 100, 1000, 10000, 50000, 65535})
    for (double v : {100.0, 1000.0, 10000.0, 100000.0}) {
      const FeedRun f = run_feed(r, v);
      const uint64_t prepare = std::max<uint64_t>(f.iterations, 2 * 16 + 3);
      // Saturation when F * N >= M: F = M / N (10^-3 1/min), contour feed F * length.
      const double v_sat = 60.0 * 1e6 / double(f.iterations) * (M_PI / 2 * double(r) * 0.001);
      std::printf("| %lld | %llu | %.0f | %.3f | %llu | %.1f | %+.3f %% | %s | %llu | %llu | %.0f |\n",
                  static_cast<long long>(r), static_cast<unsigned long long>(f.iterations), v,
                  f.feed / 1000.0, static_cast<unsigned long long>(f.clocks), f.ideal_clocks,
                  100.0 * (double(f.clocks) - f.ideal_clocks) / f.ideal_clocks,
                  f.saturated ? "yes" : "no", static_cast<unsigned long long>(prepare),
                  static_cast<unsigned long long>(f.gap_clocks), v_sat);
    }
}

}  // namespace
}  // namespace ncinterp::bench

int main(int argc, char** argv) {
  CLI::App app{"circle_bench: circle DDA measurements for docs/circle-dda.md"};
  std::string section = "all";
  int count = 100000;
  uint64_t seed = 1;
  unsigned max_width = 6;
  app.add_option("--section", section, "scheme|quadrants|random|exhaustive|feed|all")
      ->check(CLI::IsMember({"scheme", "quadrants", "random", "exhaustive", "feed", "all"}));
  app.add_option("--arcs", count, "random arcs");
  app.add_option("--seed", seed, "random seed");
  app.add_option("--max-width", max_width, "largest W of the exhaustive section")
      ->check(CLI::Range(2, 8));
  CLI11_PARSE(app, argc, argv);

  std::string command;
  for (int i = 0; i < argc; ++i) command += (i ? " " : "") + std::string(argv[i]);
  std::printf("Command: `%s`\n", command.c_str());
  using namespace ncinterp::bench;
  if (section == "scheme" || section == "all") scheme_section();
  if (section == "quadrants" || section == "all") quadrants_section();
  if (section == "random" || section == "all") random_section(count, seed);
  if (section == "exhaustive" || section == "all") exhaustive_section(max_width);
  if (section == "feed" || section == "all") feed_section();
  return 0;
}
