// G-code contours, the subset CAM tools write for 2-D profiles (docs/inputs.md):
// G0/G1/G2/G3 (arcs by I/J or R), G17, G20/G21, G90/G91, G40, G94, comments in ( ) or
// after ';', N line numbers, '%' lines, F/S/T/M words (feed comes from the CLI, so F is
// read and ignored), Z-only moves (skipped: the contour is 2-D). G41/G42 are refused with a
// message pointing to --cutter-radius/--side; anything else unknown is refused too.
// The machine starts at (0, 0); every move becomes a segment (G0 marked rapid).
#include <cctype>
#include <cmath>
#include <cstdlib>
#include <map>
#include <sstream>

#include "geometry/arc_fit.h"
#include "inputs/contour_inputs.h"

namespace ncinterp::firststage {
namespace {

struct Word {
  char letter;
  double value;
  std::string text;
};

std::string fmt(double v) {
  std::ostringstream s;
  s.precision(10);
  s << v;
  return s.str();
}

// Splits one line into words, dropping comments. Throws on malformed text.
std::vector<Word> words_of(const std::string& raw, const std::string& file, int line) {
  std::vector<Word> words;
  size_t i = 0;
  const size_t n = raw.size();
  while (i < n) {
    const char ch = raw[i];
    if (ch == ';') break;
    if (ch == '(') {
      const size_t close = raw.find(')', i);
      if (close == std::string::npos) throw InputError(file, line, "comment '(' is not closed");
      i = close + 1;
      continue;
    }
    if (std::isspace(static_cast<unsigned char>(ch)) || ch == '%') {
      ++i;
      continue;
    }
    if (!std::isalpha(static_cast<unsigned char>(ch)))
      throw InputError(file, line, std::string("unexpected character '") + ch + "' at column " +
                                       std::to_string(i + 1));
    const char letter = static_cast<char>(std::toupper(static_cast<unsigned char>(ch)));
    size_t j = i + 1;
    while (j < n && std::isspace(static_cast<unsigned char>(raw[j]))) ++j;
    const size_t start = j;
    if (j < n && (raw[j] == '+' || raw[j] == '-')) ++j;
    while (j < n && (std::isdigit(static_cast<unsigned char>(raw[j])) || raw[j] == '.')) ++j;
    const std::string num = raw.substr(start, j - start);
    char* end = nullptr;
    const double v = std::strtod(num.c_str(), &end);
    if (num.empty() || end != num.c_str() + num.size() || !std::isfinite(v))
      throw InputError(file, line, std::string("word ") + letter + " needs a number at column " +
                                       std::to_string(i + 1));
    words.push_back({letter, v, std::string(1, letter) + num});
    i = j;
  }
  return words;
}

}  // namespace

Contour parse_gcode(const std::string& text, const std::string& file) {
  Contour contour;
  contour.file = file;
  std::istringstream in(text);
  std::string raw;
  int line = 0;
  int motion = -1;  // modal G0..G3, none yet
  bool absolute = true;
  double scale = 1.0;  // mm per program unit
  Vec2 cur{0.0, 0.0};
  bool ended = false;
  while (std::getline(in, raw)) {
    ++line;
    if (ended) {
      if (words_of(raw, file, line).empty()) continue;
      throw InputError(file, line, "block after the end of the program (M2/M30)");
    }
    const std::vector<Word> words = words_of(raw, file, line);
    std::map<char, double> axis;
    int new_motion = -1;
    for (const Word& w : words) {
      const auto fail = [&](const std::string& what) { throw InputError(file, line, what); };
      switch (w.letter) {
        case 'G': {
          const double g = w.value;
          if (g == 0 || g == 1 || g == 2 || g == 3) {
            if (new_motion >= 0) fail("two motion codes in one block");
            new_motion = static_cast<int>(g);
          } else if (g == 17 || g == 40 || g == 94) {
            // XY plane, compensation off, feed per minute: the defaults here.
          } else if (g == 20) {
            scale = 25.4;
          } else if (g == 21) {
            scale = 1.0;
          } else if (g == 90) {
            absolute = true;
          } else if (g == 91) {
            absolute = false;
          } else if (g == 41 || g == 42) {
            fail(w.text + ": cutter compensation in the program is not supported; remove "
                 "G41/G42/D and use --cutter-radius R --side " + std::string(g == 41 ? "left" : "right"));
          } else if (g == 18 || g == 19) {
            fail(w.text + ": only the XY plane (G17) is supported");
          } else {
            fail("unsupported code " + w.text);
          }
          break;
        }
        case 'M': {
          const double m = w.value;
          if (m == 2 || m == 30) ended = true;
          else if (!(m == 0 || m == 1 || m == 3 || m == 4 || m == 5 || m == 6 || m == 7 ||
                     m == 8 || m == 9))
            fail("unsupported code " + w.text);
          break;
        }
        case 'N': case 'F': case 'S': case 'T': break;
        case 'D': fail(w.text + ": tool offsets (D) are not supported; use --cutter-radius");
        case 'X': case 'Y': case 'Z': case 'I': case 'J': case 'R':
          if (axis.count(w.letter)) fail(std::string("word ") + w.letter + " twice in one block");
          axis[w.letter] = w.value;
          break;
        case 'K': fail("K (arc centre in Z) is not supported: XY contours only");
        case 'P': fail("P (arc turns / dwell) is not supported");
        default: fail("unsupported word " + w.text);
      }
    }
    if (new_motion >= 0) motion = new_motion;
    const bool has_xy = axis.count('X') || axis.count('Y');
    const bool has_arc_words = axis.count('I') || axis.count('J') || axis.count('R');
    if (!has_xy && !has_arc_words) continue;  // no XY motion (Z-only moves are skipped)
    if (axis.count('Z') && has_xy)
      throw InputError(file, line, "XY move with Z: only 2-D contours are supported");
    if (motion < 0) throw InputError(file, line, "move without a motion code (G0/G1/G2/G3)");
    Vec2 to = cur;
    if (axis.count('X')) to.x = (absolute ? 0.0 : cur.x) + scale * axis['X'];
    if (axis.count('Y')) to.y = (absolute ? 0.0 : cur.y) + scale * axis['Y'];
    Segment seg;
    std::string kind;
    if (motion <= 1) {
      if (has_arc_words) throw InputError(file, line, "I/J/R in a straight move (G0/G1)");
      if (norm(to - cur) == 0.0) continue;  // a move to where we are: nothing to cut
      seg = Segment::line(cur, to);
      seg.rapid = motion == 0;
      kind = motion == 0 ? "G0" : "G1";
    } else {
      const bool ccw = motion == 3;
      kind = ccw ? "G3" : "G2";
      Vec2 centre;
      if (axis.count('R')) {
        if (axis.count('I') || axis.count('J'))
          throw InputError(file, line, "arc with both R and I/J");
        if (norm(to - cur) == 0.0)
          throw InputError(file, line, "full circle with R: give the centre with I/J");
        if (!arc_centre_from_radius(cur, to, scale * axis['R'], ccw, &centre))
          throw InputError(file, line, "arc radius R" + fmt(axis['R']) +
                                           " is shorter than half the distance to the end point");
      } else {
        if (!axis.count('I') && !axis.count('J'))
          throw InputError(file, line, "arc without a centre (I/J) or radius (R)");
        centre = cur + scale * Vec2{axis.count('I') ? axis['I'] : 0.0, axis.count('J') ? axis['J'] : 0.0};
        if (norm(cur - centre) == 0.0) throw InputError(file, line, "arc of zero radius");
        const double off = arc_radius_mismatch(cur, to, centre);
        if (off > kArcEndTolerance)
          throw InputError(file, line, "arc end is " + fmt(off) +
                                           " mm off the circle about I/J (tolerance " +
                                           fmt(kArcEndTolerance) + " mm)");
      }
      seg = arc_through(cur, to, centre, ccw);
    }
    seg.source_line = line;
    seg.source_index = static_cast<int>(contour.element_names.size());
    contour.element_names.push_back("line " + std::to_string(line) + " (" + kind + ")");
    contour.segments.push_back(seg);
    cur = to;
  }
  if (contour.segments.empty()) throw InputError(file, line, "no XY motion in the program");
  return contour;
}

}  // namespace ncinterp::firststage
