// Input kind by extension and file reading (see contour_inputs.h).
#include <algorithm>
#include <cctype>
#include <cmath>
#include <stdexcept>
#include <string>
#include <fstream>
#include <sstream>

#include "inputs/contour_inputs.h"

namespace ncinterp::firststage {

InputKind input_kind_of(const std::string& path) {
  const auto dot = path.find_last_of('.');
  std::string ext = dot == std::string::npos ? "" : path.substr(dot + 1);
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return std::tolower(c); });
  if (ext == "json") return InputKind::kJson;
  // .tap: what Mach3, Fusion 360, SheetCam and pcb-gcode posts name their G-code.
  if (ext == "nc" || ext == "ngc" || ext == "gcode" || ext == "tap") return InputKind::kGcode;
  if (ext == "dat") return InputKind::kAirfoil;
  throw InputError(path, 0,
                   "unknown input kind '." + ext +
                       "': use .json (contour), .nc/.ngc/.gcode/.tap (G-code) or .dat (airfoil)");
}

const char* input_kind_name(InputKind kind) {
  switch (kind) {
    case InputKind::kJson: return "json";
    case InputKind::kGcode: return "gcode";
    case InputKind::kAirfoil: return "airfoil";
  }
  return "?";
}

namespace {

// No machine has a table of a kilometre: a larger coordinate is a typo or garbage, refused
// where it is read (the first stage then checks the interpolator's own position range).
// An arc's centre too: a centre 1e15 mm away makes a "circle" whose points a double holds
// only to about a millimetre (found by the gcode fuzzer: a tape 0.57 mm off at tol 0.5).
constexpr double kMaxCoordinateMm = 1e6;

Contour checked(Contour c) {
  const auto check = [&c](Vec2 p, int line, const char* what) {
    if (!(std::fabs(p.x) <= kMaxCoordinateMm && std::fabs(p.y) <= kMaxCoordinateMm))
      throw InputError(c.file, line,
                       std::string(what) + " out of range: (" + std::to_string(p.x) + ", " +
                           std::to_string(p.y) + ") mm, the limit is +-1e6 mm");
  };
  for (const Segment& s : c.segments) {
    check(s.start(), s.source_line, "coordinate");
    check(s.end(), s.source_line, "coordinate");
    if (s.is_arc()) check(s.centre(), s.source_line, "arc centre");
  }
  return c;
}

}  // namespace

Contour read_contour(const std::string& path, const InputOptions& options) {
  const InputKind kind = input_kind_of(path);
  if (kind == InputKind::kAirfoil && !(options.airfoil_chord_mm > 0))
    throw std::invalid_argument("--airfoil-chord must be > 0 mm (the airfoil's length)");
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError(path, 0, "cannot open the file");
  std::ostringstream text;
  text << in.rdbuf();
  return parse_contour(kind, text.str(), path, options);
}

Contour parse_contour(InputKind kind, const std::string& text, const std::string& file,
                      const InputOptions& options) {
  switch (kind) {
    case InputKind::kJson: return checked(parse_json_contour(text, file));
    case InputKind::kGcode: return checked(parse_gcode(text, file, options.cut_z_mm));
    case InputKind::kAirfoil: return checked(parse_airfoil(text, file, options.airfoil_chord_mm));
  }
  throw InputError(file, 0, "unknown input kind");
}

}  // namespace ncinterp::firststage
