// firststage_bench: the measurements of docs/first-stage.md, printed as Markdown tables
// under the command that produced them.
// Sections:
//   circle  chords per method for a circle R = 50 mm at delta 0.01 mm, against the theory
//   airfoil chords per method for the NACA 2412 (100 mm chord) at delta 0.01 and 0.001 mm
//   arcs    method 3 against the two-sided lower bound and grbl's arc rule, circles of
//           many radii and random arcs
//   speed   chords per second on a long contour of tangent arcs and cubic parabolas
// Idea: every count comes from run_first_stage() exactly as `ncinterp tape` runs it; the
// bounds from measure/chord_bounds.h; the deviation column from the independent dense
// measure (measure/deviation_meter.h), so each table shows the chords hold delta'.
#include <CLI/CLI.hpp>
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <random>
#include <string>
#include <vector>

#include "firststage.h"
#include "inputs/contour_inputs.h"
#include "measure/chord_bounds.h"
#include "measure/deviation_meter.h"

namespace ncinterp::bench {
namespace {

using namespace ncinterp::firststage;

Contour contour_of(Vec2 origin, std::vector<Segment> segs) {
  return contour_from_segments("bench", origin, std::move(segs));
}

Contour circle(double r) { return contour_of({r, 0}, {Segment::arc({0, 0}, r, 0.0, 2 * M_PI)}); }

// Smooth pieces of a contour: runs between corners (chords may not cross a corner).
int smooth_pieces(const Contour& c) {
  int pieces = c.segments.empty() ? 0 : 1;
  for (size_t i = 1; i < c.segments.size(); ++i)
    if (!smooth_joint(c.segments[i - 1], c.segments[i])) ++pieces;
  return pieces;
}

const char* method_name(int m) { return m == 1 ? "1 trial" : m == 2 ? "2 one-sided" : "3 two-sided"; }

struct Row {
  long chords = 0;
  double deviation_mm = 0.0;  // measured, contour vs chord path
  double chord_delta_mm = 0.0;
};

Row run(const Contour& c, int method, double tol, double budget_blu, bool measure = true) {
  FirstStageOptions o;
  o.method = method;
  o.tol_mm = tol;
  o.budget_blu = budget_blu;
  // The deviation is measured with a finer grid for the finer tolerance; the BLU must be
  // well below delta for the chords to approach it.
  o.blu_mm = tol >= 0.005 ? 0.001 : 0.0001;
  const FirstStageResult r = run_first_stage(c, o);
  Row row;
  row.chords = r.planner.chords;
  row.chord_delta_mm = r.chord_delta_mm;
  if (measure)
    row.deviation_mm = measure_deviation(c, r.contour_start, r.contour_moves, o.blu_mm, tol / 8).max_mm;
  return row;
}

void circle_section() {
  const Contour c = circle(50.0);
  const double tol = 0.01, r = 50.0;
  const double one_sided = 2 * M_PI * r / (2 * std::sqrt(tol * (2 * r - tol)));
  const double two_sided = 2 * M_PI * r / (4 * std::sqrt(r * tol));
  std::printf("\n### Circle R = 50 mm, delta = 0.01 mm, BLU 0.001 mm\n\n");
  std::printf("Theory at the full delta: one-sided %.1f chords, two-sided %.1f. grbl's arc rule: %ld "
              "segments.\n\n",
              one_sided, two_sided, grbl_arc_segments(c, tol));
  std::printf("| method | budget (BLU) | delta' (mm) | chords | theory at delta' | chords / theory |"
              " max deviation measured (mm) |\n|---|---:|---:|---:|---:|---:|---:|\n");
  for (double budget : {0.0, 1.0}) {
    for (int m = 1; m <= 3; ++m) {
      const Row row = run(c, m, tol, budget);
      const double d = row.chord_delta_mm;
      const double theory = m == 3 ? 2 * M_PI * r / (4 * std::sqrt(r * d))
                                   : 2 * M_PI * r / (2 * std::sqrt(d * (2 * r - d)));
      std::printf("| %s | %.0f | %.4f | %ld | %.1f | %.3f | %.5f |\n", method_name(m), budget, d,
                  row.chords, theory, row.chords / theory, row.deviation_mm);
    }
  }
}

void airfoil_section(const std::string& file) {
  const Contour c = read_contour(file, {});
  std::printf("\n### NACA 2412, 100 mm chord (`%s`), budget 1 BLU\n\n",
              file.substr(file.find_last_of('/') + 1).c_str());
  std::printf("%zu spline pieces and the trailing-edge line; %d smooth pieces (the trailing edge "
              "is a corner).\n\n",
              c.segments.size() - 1, smooth_pieces(c));
  std::printf("| delta (mm) | BLU (mm) | method | chords | two-sided bound at delta' | chords / bound |"
              " max deviation measured (mm) |\n|---:|---:|---|---:|---:|---:|---:|\n");
  for (double tol : {0.01, 0.001}) {
    for (int m = 1; m <= 3; ++m) {
      const Row row = run(c, m, tol, 1.0);
      const double bound = two_sided_lower_bound(c, row.chord_delta_mm);
      std::printf("| %.3f | %s | %s | %ld | %.1f | %.3f | %.5f |\n", tol, tol >= 0.005 ? "0.001" : "0.0001",
                  method_name(m), row.chords, bound, row.chords / bound, row.deviation_mm);
    }
  }
}

// Random arcs (radius 0.5 .. 500 mm, sweep up to a full turn), fixed seed.
std::vector<Contour> random_arcs(int count, uint64_t seed) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  std::vector<Contour> out;
  for (int i = 0; i < count; ++i) {
    const double r = std::exp(std::log(0.5) + u(rng) * std::log(1000.0));
    const double sweep = (0.2 + u(rng) * (2 * M_PI - 0.2)) * (u(rng) < 0.5 ? -1 : 1);
    const double a0 = u(rng) * 2 * M_PI;
    const Segment s = Segment::arc({0, 0}, r, a0, sweep);
    out.push_back(contour_of(s.start(), {s}));
  }
  return out;
}

// The end effect: a chain whose two ends lie on the curve (every open arc, and a circle
// started on it) has a first and a last chord that reach delta on one side only, each
// (2 + sqrt 2) / 4 of a two-sided chord; so at least ceil(bound + 1 - sqrt(2) / 2) chords.
constexpr double kEndEffect = 1.0 - M_SQRT2 / 2.0;

void arcs_section(int count, uint64_t seed) {
  const double tol = 0.01;
  std::printf("\n### Method 3 against the two-sided lower bound and grbl's arc rule, delta = 0.01 mm\n\n");
  std::printf("Bound: integral of sqrt(kappa / (16 delta')) ds with delta' = delta - 1 BLU = 0.009 mm. "
              "The allowance: 1.05 x bound + 1 per smooth piece. With both chain ends on the "
              "curve no chain can have fewer than ceil(bound + %.3f) chords (first and last chord "
              "one-sided), so the table also shows ceil(1.05 x bound + %.3f). grbl: floor(|theta| R / 2 / "
              "sqrt(delta (2R - delta))) segments per arc at the full delta (its pulse path is not "
              "held to delta).\n\n",
              kEndEffect, kEndEffect);
  std::printf("| arc | method 3 chords | bound | chords / bound | <= 1.05 x bound + 1 |"
              " <= ceil(1.05 x bound + %.3f) | grbl segments | grbl / method 3 |\n"
              "|---|---:|---:|---:|---|---|---:|---:|\n",
              kEndEffect);
  const auto within = [](long n, double b) { return n <= 1.05 * b + 1; };
  const auto within_ends = [](long n, double b) { return n <= std::ceil(1.05 * b + kEndEffect); };
  for (double r : {1.0, 2.0, 5.0, 10.0, 50.0, 200.0, 1000.0}) {
    const Contour c = circle(r);
    const Row row = run(c, 3, tol, 1.0, false);
    const double bound = two_sided_lower_bound(c, row.chord_delta_mm);
    const long grbl = grbl_arc_segments(c, tol);
    std::printf("| circle R = %g mm | %ld | %.1f | %.3f | %s | %s | %ld | %.2f |\n", r, row.chords, bound,
                row.chords / bound, within(row.chords, bound) ? "yes" : "NO",
                within_ends(row.chords, bound) ? "yes" : "NO", grbl, static_cast<double>(grbl) / row.chords);
  }
  long chords = 0, grbl = 0, ok = 0, ok_ends = 0, grbl_fewer = 0, most_fewer = 0;
  double bound = 0, longest_fewer = 0;
  for (const Contour& c : random_arcs(count, seed)) {
    const Row row = run(c, 3, tol, 1.0, false);
    const double b = two_sided_lower_bound(c, row.chord_delta_mm);
    const long g = grbl_arc_segments(c, tol);
    chords += row.chords;
    bound += b;
    grbl += g;
    ok += within(row.chords, b);
    ok_ends += within_ends(row.chords, b);
    if (g < row.chords) {
      ++grbl_fewer;
      longest_fewer = std::max(longest_fewer, std::fabs(c.segments[0].sweep()) * c.segments[0].radius());
      most_fewer = std::max(most_fewer, g);
    }
  }
  std::printf("| %d random arcs (seed %llu), total | %ld | %.1f | %.3f | %ld of %d | %ld of %d | %ld | %.2f |\n",
              count, static_cast<unsigned long long>(seed), chords, bound, chords / bound, ok, count, ok_ends,
              count, grbl, static_cast<double>(grbl) / chords);
  std::printf("\nRandom arcs: radius 0.5 to 500 mm (log-uniform), sweep 0.2 rad to a full turn. grbl "
              "writes fewer segments than method 3 on %ld of them, arcs at most %.2f mm long where grbl "
              "writes at most %ld segments: its floor() rounds the count down, so its segments are never "
              "closer than delta to the arc, which on a short arc saves a whole segment.\n",
              grbl_fewer, longest_fewer, most_fewer);
}

// A long contour: tangent arcs (radius 1 .. 8 mm, alternating sides) and, every fifth
// piece, a cubic parabola y = a x^3 over 10 mm joined at a corner.
Contour long_contour(int pieces, uint64_t seed) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> rad(1.0, 8.0), ang(0.3, 1.2);
  std::vector<Segment> segs;
  Vec2 p{0, 0};
  double heading = 0.0;
  for (int i = 0; i < pieces; ++i) {
    if (i % 5 == 4) {
      const double a = 0.002 * (i % 2 ? 1 : -1);  // y = p.y + a (x - p.x)^3
      const Segment s = Segment::cubic_parabola_local(p.x, 10.0, p.y, 0.0, 0.0, a * 1000.0);
      segs.push_back(s);
      p = s.end();
      const Vec2 t = s.eval(1.0).d1;
      heading = std::atan2(t.y, t.x);
      continue;
    }
    const bool ccw = i % 2 == 0;
    const double r = rad(rng), a = ang(rng);
    const Vec2 left{-std::sin(heading), std::cos(heading)};
    const Vec2 centre = p + (ccw ? r : -r) * left;
    const Segment s = Segment::arc(centre, r, std::atan2(p.y - centre.y, p.x - centre.x), ccw ? a : -a);
    segs.push_back(s);
    p = s.end();
    heading += ccw ? a : -a;
  }
  return contour_of({0, 0}, segs);
}

void speed_section(int pieces, int repeats) {
  const Contour c = long_contour(pieces, 11);
  std::printf("\n### Speed: chords per second, one core\n\n");
  std::printf("Long contour: %d pieces (tangent arcs of radius 1 to 8 mm; every fifth a cubic parabola "
              "over 10 mm), delta 0.01 mm, BLU 0.001 mm. Time of run_first_stage() (planning, grid, "
              "register split), best of %d runs.\n\n",
              pieces, repeats);
  std::printf("| method | chords | seconds | chords per second |\n|---|---:|---:|---:|\n");
  for (int m = 1; m <= 3; ++m) {
    FirstStageOptions o;
    o.method = m;
    double best = 1e300;
    long chords = 0;
    for (int k = 0; k < repeats; ++k) {
      const auto t0 = std::chrono::steady_clock::now();
      const FirstStageResult r = run_first_stage(c, o);
      best = std::min(best, std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count());
      chords = r.planner.chords;
    }
    std::printf("| %s | %ld | %.3f | %.0f |\n", method_name(m), chords, best, chords / best);
  }
}

}  // namespace
}  // namespace ncinterp::bench

int main(int argc, char** argv) {
  CLI::App app{"firststage_bench: first-stage measurements for docs/first-stage.md"};
  std::string section = "all";
  std::string airfoil = std::string(NCINTERP_EXAMPLES_DIR) + "/naca2412_selig.dat";
  int arcs = 2000, pieces = 50000, repeats = 3;
  uint64_t seed = 1;
  app.add_option("--section", section, "circle|airfoil|arcs|speed|all")
      ->check(CLI::IsMember({"circle", "airfoil", "arcs", "speed", "all"}));
  app.add_option("--airfoil", airfoil, "airfoil .dat file (100 mm chord)");
  app.add_option("--arcs", arcs, "random arcs in the arcs section");
  app.add_option("--seed", seed, "random seed of the arcs section");
  app.add_option("--pieces", pieces, "pieces of the long contour (speed section)");
  app.add_option("--repeats", repeats, "timed runs per method (speed section)");
  CLI11_PARSE(app, argc, argv);

  std::string command;
  for (int i = 0; i < argc; ++i) command += (i ? " " : "") + std::string(argv[i]);
  std::printf("Command: `%s`\n", command.c_str());
  using namespace ncinterp::bench;
  try {
    if (section == "circle" || section == "all") circle_section();
    if (section == "airfoil" || section == "all") airfoil_section(airfoil);
    if (section == "arcs" || section == "all") arcs_section(arcs, seed);
    if (section == "speed" || section == "all") speed_section(pieces, repeats);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "firststage_bench: %s\n", e.what());
    return 1;
  }
  return 0;
}
