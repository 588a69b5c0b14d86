// Random part contours for the soak and the short random regression, written as input
// files (G-code, JSON, airfoil .dat) and read back through the first stage's own readers,
// so every case runs the whole chain a user runs.
// Idea: a few shapes cover what the first stage and the interpolator must handle:
//   part     closed polygon (G-code) with convex and concave fillet arcs, a rapid to a hole
//            cut as a full circle;
//   table    reference-point table (Tamm's profiles) closed by straight sides;
//   cubic    chain of cubic parabolas y = Ax^3 + Bx^2 + Cx + D, corners between them;
//   airfoil  NACA 4-digit profile in the Selig format;
//   circle   one full circle, either direction.
// Every number in a generated file is printed with enough digits that the reader sees the
// shape the generator meant (arc ends on their circles within the readers' tolerance).
#pragma once
#include <cstdint>
#include <random>
#include <string>

#include "regression_support.h"

namespace ncinterp::regression {

enum class ShapeKind { kPart, kTable, kCubic, kAirfoil, kCircle };
const char* shape_name(ShapeKind kind);

struct GeneratedInput {
  ShapeKind kind;
  std::string file_name;  // e.g. "case17.nc": the extension selects the reader
  std::string text;
  double airfoil_chord_mm = 100.0;
};

GeneratedInput random_input(ShapeKind kind, std::mt19937_64& rng);

// Options a soak case varies: chord method, tolerance, register width, cutter offset (on
// shapes without arcs as arc blocks), and a feed giving about `seconds` of machine time.
struct RandomCaseLimits {
  bool arcs_circle_allowed = true;   // contours with arcs may be cut with G02/G03 blocks
  bool cutter_allowed = true;
  double seconds = 0.5;              // machine time of the whole contour, about
};

// A complete random case (contour parsed from the generated text, first-stage options,
// check setup) named "<seed>-<shape>". Throws what the readers throw on a bad generation.
Case random_case(uint64_t seed, const RandomCaseLimits& limits, GeneratedInput* input = nullptr);

// Length of a contour's cutting path, mm (dense sampling; for choosing a feed).
double contour_length_mm(const firststage::Contour& contour);

}  // namespace ncinterp::regression
