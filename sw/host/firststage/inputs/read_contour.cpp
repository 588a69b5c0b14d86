// Input kind by extension and file reading (see contour_inputs.h).
#include <algorithm>
#include <cctype>
#include <fstream>
#include <sstream>

#include "inputs/contour_inputs.h"

namespace ncinterp::firststage {

InputKind input_kind_of(const std::string& path) {
  const auto dot = path.find_last_of('.');
  std::string ext = dot == std::string::npos ? "" : path.substr(dot + 1);
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return std::tolower(c); });
  if (ext == "json") return InputKind::kJson;
  if (ext == "nc" || ext == "ngc" || ext == "gcode") return InputKind::kGcode;
  if (ext == "dat") return InputKind::kAirfoil;
  throw InputError(path, 0,
                   "unknown input kind '." + ext +
                       "': use .json (contour), .nc/.ngc/.gcode (G-code) or .dat (airfoil)");
}

const char* input_kind_name(InputKind kind) {
  switch (kind) {
    case InputKind::kJson: return "json";
    case InputKind::kGcode: return "gcode";
    case InputKind::kAirfoil: return "airfoil";
  }
  return "?";
}

Contour read_contour(const std::string& path, const InputOptions& options) {
  const InputKind kind = input_kind_of(path);
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError(path, 0, "cannot open the file");
  std::ostringstream text;
  text << in.rdbuf();
  switch (kind) {
    case InputKind::kJson: return parse_json_contour(text.str(), path);
    case InputKind::kGcode: return parse_gcode(text.str(), path);
    case InputKind::kAirfoil: return parse_airfoil(text.str(), path, options.airfoil_chord_mm);
  }
  throw InputError(path, 0, "unknown input kind");
}

}  // namespace ncinterp::firststage
