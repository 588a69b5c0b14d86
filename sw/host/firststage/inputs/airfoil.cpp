// Airfoil coordinates (UIUC database formats, docs/inputs.md):
//  Selig: a name line, then "x y" per line from the trailing edge over the upper surface
//         to the leading edge and back over the lower surface.
//  Lednicer: a name line, a line "NU. NL." (point counts), then the upper surface from the
//         leading to the trailing edge, then the lower surface likewise (blank lines
//         between the blocks).
// Both become one contour in Selig order, scaled by the chord length: a C2 parametric
// spline through all points, and, when the trailing edge is open, a straight closing line
// from the lower back to the upper trailing edge point. The trailing edge points are corners.
#include <cmath>
#include <sstream>

#include "inputs/contour_inputs.h"
#include "inputs/parametric_spline.h"

namespace ncinterp::firststage {
namespace {

struct Row {
  int line;
  std::vector<double> values;
};

// Non-empty lines after the name, as numbers; blank lines are reported as empty rows.
std::vector<Row> rows_of(const std::string& text, const std::string& file, std::string* name) {
  std::istringstream in(text);
  std::string raw;
  std::vector<Row> rows;
  int line = 0;
  while (std::getline(in, raw)) {
    ++line;
    if (!raw.empty() && raw.back() == '\r') raw.pop_back();
    if (line == 1) {
      *name = raw;
      continue;
    }
    std::istringstream ls(raw);
    Row row{line, {}};
    std::string tok;
    while (ls >> tok) {
      char* end = nullptr;
      const double v = std::strtod(tok.c_str(), &end);
      if (end != tok.c_str() + tok.size() || !std::isfinite(v))
        throw InputError(file, line, "'" + tok + "' is not a number");
      row.values.push_back(v);
    }
    if (!row.values.empty() && row.values.size() != 2)
      throw InputError(file, line, "expected two numbers \"x y\", found " +
                                       std::to_string(row.values.size()));
    rows.push_back(row);
  }
  return rows;
}

}  // namespace

Contour parse_airfoil(const std::string& text, const std::string& file, double chord_mm) {
  std::string name;
  std::vector<Row> rows = rows_of(text, file, &name);
  std::vector<Row> data;
  for (const Row& r : rows)
    if (!r.values.empty()) data.push_back(r);
  if (data.empty()) throw InputError(file, 1, "no coordinates after the name line");
  std::vector<Vec2> pts;
  std::vector<int> lines;
  // Lednicer: the first data row holds the point counts (> 1, coordinates are <= ~1).
  if (data[0].values[0] > 1.5 && data[0].values[1] > 1.5) {
    const double nu = data[0].values[0], nl = data[0].values[1];
    if (nu != std::floor(nu) || nl != std::floor(nl))
      throw InputError(file, data[0].line, "Lednicer point counts must be whole numbers");
    // Compared as doubles first: a count like 1e38 has no size_t (found by the airfoil
    // fuzzer: UBSan, a float-to-integer conversion out of range).
    if (static_cast<double>(data.size() - 1) != nu + nl) {
      std::ostringstream what;
      what << "Lednicer header announces " << nu << " + " << nl << " points, the file has "
           << data.size() - 1;
      throw InputError(file, data.back().line, what.str());
    }
    const size_t upper = static_cast<size_t>(nu);
    for (size_t i = upper; i >= 1; --i) {  // upper surface, trailing edge first
      pts.push_back({data[i].values[0], data[i].values[1]});
      lines.push_back(data[i].line);
    }
    for (size_t i = upper + 1; i < data.size(); ++i) {
      pts.push_back({data[i].values[0], data[i].values[1]});
      lines.push_back(data[i].line);
    }
  } else {
    for (const Row& r : data) {
      pts.push_back({r.values[0], r.values[1]});
      lines.push_back(r.line);
    }
  }
  // Drop repeated points (Lednicer files repeat the leading edge).
  std::vector<Vec2> uniq;
  std::vector<int> uniq_lines;
  for (size_t i = 0; i < pts.size(); ++i) {
    if (!uniq.empty() && norm(pts[i] - uniq.back()) <= 1e-12) continue;
    uniq.push_back(pts[i]);
    uniq_lines.push_back(lines[i]);
  }
  if (uniq.size() < 5) throw InputError(file, lines.back(), "an airfoil needs at least 5 distinct points");
  for (size_t i = 0; i < uniq.size(); ++i) {
    if (std::fabs(uniq[i].x) > 2.0 || std::fabs(uniq[i].y) > 2.0)
      throw InputError(file, uniq_lines[i], "coordinate out of range: airfoil files give x, y in chord lengths (0..1)");
  }
  const bool closed_te = norm(uniq.front() - uniq.back()) <= 1e-12;
  std::vector<Vec2> scaled;
  for (const Vec2& v : uniq) scaled.push_back(chord_mm * v);
  Contour contour;
  contour.file = file;
  contour.origin = scaled.front();
  std::vector<Segment> pieces = natural_spline(scaled);
  for (size_t i = 0; i < pieces.size(); ++i) {
    pieces[i].source_line = uniq_lines[i];
    pieces[i].source_index = static_cast<int>(i);
    contour.element_names.push_back("spline piece " + std::to_string(i + 1) + " (lines " +
                                    std::to_string(uniq_lines[i]) + "-" +
                                    std::to_string(uniq_lines[i + 1]) + ")");
    contour.segments.push_back(pieces[i]);
  }
  if (!closed_te) {
    Segment te = Segment::line(scaled.back(), scaled.front());
    te.source_line = uniq_lines.back();
    te.source_index = static_cast<int>(contour.element_names.size());
    contour.element_names.push_back("trailing edge (line)");
    contour.segments.push_back(te);
  }
  return contour;
}

}  // namespace ncinterp::firststage
