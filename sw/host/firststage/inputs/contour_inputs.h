// Reading part contours: JSON (lines, arcs, cubic parabolas, reference-point tables),
// G-code (a CAM subset) and airfoil coordinates (UIUC Selig and Lednicer). docs/inputs.md
// describes each format. Every reader throws InputError "FILE:LINE: what is wrong".
#pragma once
#include <limits>
#include <string>

#include "geometry/contour.h"
#include "inputs/input_error.h"

namespace ncinterp::firststage {

struct InputOptions {
  double airfoil_chord_mm = 100.0;  // .dat coordinates are in chord lengths
  // G-code with Z words: XY moves at or below this Z are the cut, the others traverses.
  // NaN: the lowest Z the program reaches (docs/first-stage.md 1.3).
  double cut_z_mm = std::numeric_limits<double>::quiet_NaN();
};

enum class InputKind { kJson, kGcode, kAirfoil };

// Kind from the file name's extension; throws InputError for an unknown one.
InputKind input_kind_of(const std::string& path);
const char* input_kind_name(InputKind kind);
// Reads and parses `path` by its extension.
Contour read_contour(const std::string& path, const InputOptions& options);
// Parses a contour's text as read_contour() does, the range checks included (`file` names
// it in errors): what `ncinterp tape` accepts from a file, accepted from memory (fuzzers).
Contour parse_contour(InputKind kind, const std::string& text, const std::string& file,
                      const InputOptions& options);

Contour parse_json_contour(const std::string& text, const std::string& file);
Contour parse_gcode(const std::string& text, const std::string& file,
                    double cut_z_mm = std::numeric_limits<double>::quiet_NaN());
Contour parse_airfoil(const std::string& text, const std::string& file, double chord_mm);

// Tolerance for an arc's end off the circle about its stated centre (G-code and JSON).
constexpr double kArcEndTolerance = 0.002;  // mm

}  // namespace ncinterp::firststage
