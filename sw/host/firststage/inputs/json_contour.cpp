// JSON contours (docs/inputs.md): {"start": [x, y], "segments": [ {...}, ... ]} with
// segment types line, arc, cubic and table. nlohmann-json parses; since it keeps no line
// numbers, a small scan of the text finds the line where each segment object starts, so
// every message names the segment's line.
#include <algorithm>
#include <cmath>
#include <nlohmann/json.hpp>
#include <sstream>

#include "geometry/arc_fit.h"
#include "inputs/contour_inputs.h"
#include "inputs/reference_table.h"

namespace ncinterp::firststage {
namespace {

using nlohmann::json;

int line_of_offset(const std::string& text, size_t offset) {
  offset = std::min(offset, text.size());
  return 1 + static_cast<int>(std::count(text.begin(), text.begin() + offset, '\n'));
}

// Line of the key "segments" and of each object in its array (top-level key only).
std::vector<int> segment_lines(const std::string& text, int* key_line) {
  std::vector<int> lines;
  int depth = 0, line = 1, segments_depth = -1;
  bool in_string = false, escape = false;
  std::string last_string;
  size_t string_start = 0;
  for (size_t i = 0; i < text.size(); ++i) {
    const char ch = text[i];
    if (ch == '\n') ++line;
    if (in_string) {
      if (escape) escape = false;
      else if (ch == '\\') escape = true;
      else if (ch == '"') {
        in_string = false;
        last_string = text.substr(string_start, i - string_start);
      }
      continue;
    }
    if (ch == '"') {
      in_string = true;
      string_start = i + 1;
    } else if (ch == '[' || ch == '{') {
      if (ch == '[' && depth == 1 && last_string == "segments" && segments_depth < 0) {
        segments_depth = depth + 1;
        *key_line = line;
      } else if (ch == '{' && segments_depth > 0 && depth == segments_depth) {
        lines.push_back(line);
      }
      ++depth;
      last_string.clear();
    } else if (ch == ']' || ch == '}') {
      --depth;
      if (depth < segments_depth) segments_depth = -2;  // array closed: stop recording
    } else if (ch == ',') {
      last_string.clear();
    }
  }
  return lines;
}

class Reader {
 public:
  Reader(const std::string& file, int line) : file_(file), line_(line) {}
  [[noreturn]] void fail(const std::string& what) const { throw InputError(file_, line_, what); }
  double number(const json& obj, const char* key) const {
    if (!obj.contains(key)) fail(std::string("missing \"") + key + "\"");
    const json& v = obj.at(key);
    if (!v.is_number()) fail(std::string("\"") + key + "\" must be a number");
    const double d = v.get<double>();
    if (!std::isfinite(d)) fail(std::string("\"") + key + "\" is not finite");
    return d;
  }
  Vec2 point(const json& obj, const char* key) const {
    if (!obj.contains(key)) fail(std::string("missing \"") + key + "\"");
    const json& v = obj.at(key);
    if (!v.is_array() || v.size() != 2 || !v[0].is_number() || !v[1].is_number())
      fail(std::string("\"") + key + "\" must be [x, y] (two numbers, mm)");
    return {v[0].get<double>(), v[1].get<double>()};
  }
  int line() const { return line_; }

 private:
  std::string file_;
  int line_;
};

std::string fmt(double v) {
  std::ostringstream s;
  s.precision(10);
  s << v;
  return s.str();
}

// Point tolerance for "this segment starts where the last one ended".
constexpr double kJoinTolerance = 1e-6;  // mm

}  // namespace

Contour parse_json_contour(const std::string& text, const std::string& file) {
  json doc;
  try {
    doc = json::parse(text);
  } catch (const json::parse_error& e) {
    // e.what() is "[json.exception.parse_error.101] parse error at line L, column C: ..."
    std::string msg = e.what();
    const auto colon = msg.find(": ", msg.find("parse error"));
    throw InputError(file, line_of_offset(text, e.byte > 0 ? e.byte - 1 : 0),
                     "invalid JSON: " + (colon == std::string::npos ? msg : msg.substr(colon + 2)));
  } catch (const json::out_of_range& e) {
    // A number beyond a double (out_of_range.406, "number overflow parsing '1E999'") carries
    // no position: the line is the first one holding the quoted literal.
    const std::string msg = e.what();
    const size_t open = msg.find('\''), close = msg.rfind('\'');
    const std::string literal =
        open != std::string::npos && close > open ? msg.substr(open + 1, close - open - 1) : "";
    const size_t at = literal.empty() ? std::string::npos : text.find(literal);
    throw InputError(file, at == std::string::npos ? 1 : line_of_offset(text, at),
                     "invalid JSON: number out of range" +
                         (literal.empty() ? std::string() : " '" + literal + "'"));
  }
  int key_line = 1;
  const std::vector<int> lines = segment_lines(text, &key_line);
  const Reader top(file, 1);
  if (!doc.is_object()) top.fail("the contour must be a JSON object with \"start\" and \"segments\"");
  if (doc.contains("units") && doc["units"] != "mm") top.fail("\"units\" must be \"mm\"");
  Contour contour;
  contour.file = file;
  contour.origin = top.point(doc, "start");
  if (!doc.contains("segments") || !doc["segments"].is_array() || doc["segments"].empty())
    top.fail("\"segments\" must be a non-empty array");
  Vec2 cur = contour.origin;
  int index = 0;
  for (const json& s : doc["segments"]) {
    const int line = index < static_cast<int>(lines.size()) ? lines[index] : key_line;
    const Reader r(file, line);
    if (!s.is_object() || !s.contains("type") || !s["type"].is_string())
      r.fail("segment " + std::to_string(index + 1) + " needs a \"type\": line, arc, cubic or table");
    const std::string type = s["type"];
    std::vector<Segment> made;
    std::string name = "segment " + std::to_string(index + 1) + " (" + type + ", line " +
                       std::to_string(line) + ")";
    if (type == "line") {
      const Vec2 to = r.point(s, "to");
      if (norm(to - cur) == 0.0) r.fail("line of zero length");
      made.push_back(Segment::line(cur, to));
    } else if (type == "arc") {
      const Vec2 centre = r.point(s, "center");
      const Vec2 to = s.contains("to") ? r.point(s, "to") : cur;
      if (!s.contains("direction") || !s["direction"].is_string() ||
          (s["direction"] != "cw" && s["direction"] != "ccw"))
        r.fail("arc \"direction\" must be \"cw\" or \"ccw\"");
      if (norm(cur - centre) <= 0.0) r.fail("arc of zero radius (center on the start point)");
      const double off = arc_radius_mismatch(cur, to, centre);
      if (off > kArcEndTolerance)
        r.fail("arc end is " + fmt(off) + " mm off the circle about the center (tolerance " +
               fmt(kArcEndTolerance) + " mm)");
      made.push_back(arc_through(cur, to, centre, s["direction"] == "ccw"));
    } else if (type == "cubic") {
      if (!s.contains("coefficients") || !s["coefficients"].is_array() ||
          s["coefficients"].size() != 4)
        r.fail("cubic needs \"coefficients\": [A, B, C, D] for y = Ax^3 + Bx^2 + Cx + D");
      double c[4];
      for (int i = 0; i < 4; ++i) {
        if (!s["coefficients"][i].is_number()) r.fail("cubic coefficients must be numbers");
        c[i] = s["coefficients"][i].get<double>();
      }
      const double x_to = r.number(s, "x_to");
      const double y0 = ((c[0] * cur.x + c[1]) * cur.x + c[2]) * cur.x + c[3];
      if (std::fabs(y0 - cur.y) > kJoinTolerance)
        r.fail("the cubic does not pass through its start point: y(" + fmt(cur.x) + ") = " +
               fmt(y0) + ", not " + fmt(cur.y));
      if (x_to == cur.x) r.fail("cubic of zero x-range");
      made.push_back(Segment::cubic_parabola(c[0], c[1], c[2], c[3], cur.x, x_to));
    } else if (type == "table") {
      const double x0 = r.number(s, "x0"), h = r.number(s, "h");
      if (h == 0.0) r.fail("table spacing \"h\" must not be 0");
      if (!s.contains("y") || !s["y"].is_array() || s["y"].size() < 4)
        r.fail("table needs \"y\": at least 4 ordinates (third differences)");
      std::vector<double> y;
      for (const json& v : s["y"]) {
        if (!v.is_number()) r.fail("table ordinates must be numbers");
        y.push_back(v.get<double>());
      }
      if (std::fabs(x0 - cur.x) > kJoinTolerance || std::fabs(y[0] - cur.y) > kJoinTolerance)
        r.fail("the table starts at (" + fmt(x0) + ", " + fmt(y[0]) +
               ") but the contour is at (" + fmt(cur.x) + ", " + fmt(cur.y) + ")");
      made = table_segments(x0, h, y);
    } else {
      r.fail("unknown segment type \"" + type + "\": use line, arc, cubic or table");
    }
    for (Segment& m : made) {
      m.source_line = line;
      m.source_index = index;
      contour.segments.push_back(m);
    }
    contour.element_names.push_back(name);
    cur = contour.segments.back().end();
    ++index;
  }
  return contour;
}

}  // namespace ncinterp::firststage
