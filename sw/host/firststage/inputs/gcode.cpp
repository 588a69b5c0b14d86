// G-code contours, the subset CAM tools write for 2-D profiles (docs/first-stage.md 1.3):
// G0/G1/G2/G3 (arcs by I/J or R), G17, G20/G21, G90/G91, G91.1, G40, G94, comments in ( ) or
// after ';', N line numbers, '%' lines, F (feed comes from the CLI, so F is read and
// ignored). G41/G42 are refused with a message pointing to --cutter-radius/--side.
// Real CAM posts (FreeCAD, Fusion 360, Estlcam) also write machine words that mean nothing
// for the contour: O program numbers, work offsets G54..G59, tool length G43 H / G49, canned
// cycle cancel G80, home G28 (with its intermediate point), dwell G4 P, path control
// G61/G64 P, tool change T/M6, spindle S/M3/M4/M5, coolant M7/M8/M9, stops M0/M1, an arc's
// K (its centre in Z, meaningless in the XY plane). They are
// ignored, and listed in Contour::warnings (the CLI prints the list). Anything else unknown
// is refused.
// Z: the cut is the 2-D profile at the cutting depth. Without any Z word every move is part
// of the contour. With Z words, the cutting depth is the lowest Z the program reaches (or
// InputOptions::cut_z_mm); an XY move is a cut when it starts and ends at or below it, and
// a traverse (a rapid: not cut, not offset) otherwise, so the approach at safe height, the
// ramps and the roughing passes above the final depth are traverses. Z-only moves (plunges,
// retracts) are skipped.
// The machine starts at (0, 0); every move becomes a segment (G0 marked rapid).
#include <cctype>
#include <cmath>
#include <cstdlib>
#include <limits>
#include <map>
#include <set>
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

// Words ignored because they mean nothing for the contour: each kind once, with its first
// line, for the warning list.
class IgnoredWords {
 public:
  void note(const std::string& word, int line) {
    if (seen_.insert(word).second) list_.push_back(word + " (line " + std::to_string(line) + ")");
  }
  std::vector<std::string> warnings(const std::string& file) const {
    if (list_.empty()) return {};
    std::string all;
    for (const std::string& w : list_) all += (all.empty() ? "" : ", ") + w;
    return {file + ": warning: ignored, no meaning for the 2-D contour: " + all};
  }

 private:
  std::set<std::string> seen_;
  std::vector<std::string> list_;
};

// The kind of an ignored word for the list: "G54", "M8", "S", "T", "O".
std::string word_kind(const Word& w) {
  if (w.letter == 'G' || w.letter == 'M') return std::string(1, w.letter) + fmt(w.value);
  return std::string(1, w.letter);
}

}  // namespace

Contour parse_gcode(const std::string& text, const std::string& file, double cut_z_mm) {
  Contour contour;
  contour.file = file;
  IgnoredWords ignored;
  constexpr double kNoZ = std::numeric_limits<double>::quiet_NaN();
  double z = kNoZ;                                           // modal Z, mm (NaN: not known yet)
  double lowest_z = std::numeric_limits<double>::infinity();  // lowest Z reached
  std::vector<std::pair<double, double>> seg_z;              // Z at start and end of each segment
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
    // G28 (home through an intermediate point), G4 (dwell P), G43 (tool length H), G64
    // (blending tolerance P): their own words are ignored with them.
    bool home = false, has_p_code = false;
    for (const Word& w : words)
      if (w.letter == 'G' && (w.value == 28 || w.value == 4 || w.value == 64)) {
        home = home || w.value == 28;
        has_p_code = has_p_code || w.value == 4 || w.value == 64;
      }
    for (const Word& w : words) {
      const auto fail = [&](const std::string& what) { throw InputError(file, line, what); };
      switch (w.letter) {
        case 'G': {
          const double g = w.value;
          if (g == 0 || g == 1 || g == 2 || g == 3) {
            if (new_motion >= 0) fail("two motion codes in one block");
            new_motion = static_cast<int>(g);
          } else if (g == 17 || g == 40 || g == 94 || std::fabs(g - 91.1) < 1e-9) {
            // (G91.1: I/J relative to the start, which is how they are read anyway.)
            // XY plane, compensation off, feed per minute: the defaults here.
          } else if (g == 20) {
            scale = 25.4;
          } else if (g == 21) {
            scale = 1.0;
          } else if (g == 90) {
            absolute = true;
          } else if (g == 91) {
            absolute = false;
          } else if ((g >= 54 && g <= 59) || g == 28 || g == 4 || g == 43 || g == 49 ||
                     g == 80 || g == 61 || g == 64) {
            ignored.note(word_kind(w), line);  // machine set-up, not geometry
          } else if (g == 41 || g == 42) {
            fail(w.text + ": cutter compensation in the program is not supported; remove "
                 "G41/G42/D and use --cutter-radius R --side " + std::string(g == 41 ? "left" : "right"));
          } else if (g == 18 || g == 19) {
            fail(w.text + ": only the XY plane (G17) is supported");
          } else if (g == 93) {
            // .nc names both: a contour to cut, and a tape `ncinterp tape` wrote (G93).
            fail("unsupported code " + w.text + " (inverse-time feed): this is a tape, not a "
                 "contour; a contour is expected here (a tape is played by play, check, cosim)");
          } else {
            fail("unsupported code " + w.text);
          }
          break;
        }
        case 'M': {
          const double m = w.value;
          if (m == 2 || m == 30) ended = true;
          else if (m == 0 || m == 1 || m == 3 || m == 4 || m == 5 || m == 6 || m == 7 ||
                   m == 8 || m == 9)
            ignored.note(word_kind(w), line);  // stops, spindle, tool change, coolant
          else
            fail("unsupported code " + w.text);
          break;
        }
        case 'N': case 'F': break;
        case 'S': case 'T': case 'O': case 'H': ignored.note(word_kind(w), line); break;
        case 'D': fail(w.text + ": tool offsets (D) are not supported; use --cutter-radius");
        case 'X': case 'Y': case 'Z': case 'I': case 'J': case 'R':
          if (home) break;  // G28's intermediate point: not a move of the contour
          if (axis.count(w.letter)) fail(std::string("word ") + w.letter + " twice in one block");
          axis[w.letter] = w.value;
          break;
        case 'K': ignored.note("K", line); break;  // centre in Z: no meaning in the XY plane (G17)
        case 'P':
          if (!has_p_code) fail("P (arc turns) is not supported");
          break;  // the dwell time of G4, the tolerance of G64
        default: fail("unsupported word " + w.text);
      }
    }
    if (new_motion >= 0) motion = new_motion;
    const double z_before = z;
    if (axis.count('Z')) {
      z = (absolute || std::isnan(z) ? 0.0 : z) + scale * axis['Z'];
      lowest_z = std::min(lowest_z, z);
    }
    const bool has_xy = axis.count('X') || axis.count('Y');
    const bool has_arc_words = axis.count('I') || axis.count('J') || axis.count('R');
    if (!has_xy && !has_arc_words) continue;  // no XY motion (Z-only moves are skipped)
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
    seg_z.push_back({z_before, z});
    cur = to;
  }
  if (contour.segments.empty()) throw InputError(file, line, "no XY motion in the program");
  // With Z words, only the moves at the cutting depth are the contour; the rest traverse.
  if (std::isfinite(lowest_z)) {
    const double cut = std::isnan(cut_z_mm) ? lowest_z : cut_z_mm;
    const auto at_depth = [cut](double zz) { return !std::isnan(zz) && zz <= cut + 1e-9; };
    bool any_cut = false;
    for (size_t i = 0; i < contour.segments.size(); ++i) {
      if (!(at_depth(seg_z[i].first) && at_depth(seg_z[i].second))) contour.segments[i].rapid = true;
      any_cut = any_cut || !contour.segments[i].rapid;
    }
    if (!any_cut)
      throw InputError(file, 0, "no XY move at the cutting depth Z" + fmt(cut) + " mm");
  }
  contour.warnings = ignored.warnings(file);
  return contour;
}

}  // namespace ncinterp::firststage
