// G-code contours, the subset CAM tools write for 2-D profiles (docs/first-stage.md 1.3):
// G0/G1/G2/G3 (arcs by I/J or R), G17, G20/G21, G90/G91, G90.1/G91.1, G40, G94, comments
// in ( ) or after ';', N line numbers, '%' lines, F (the feed comes from the CLI, so F is
// read and ignored). Machine words that mean nothing for the contour (O program numbers,
// work offsets, tool length, home, dwell, path control, tool change, spindle, coolant,
// stops, an arc's K) are ignored and listed in Contour::warnings. Everything else is refused
// with the reason and, where there is one, what to change in the post: G41/G42 (use
// --cutter-radius), G18/G19 (vertical lead-ins), O-word subroutines and control flow,
// parameters and expressions, a '%' line with text, canned cycles, subprograms.
// Idea: the program is read into a list of XY moves with the Z at their ends, then taped
// as 2-D cutting passes. A feed move (G1/G2/G3) at a constant Z cuts at that depth; every
// depth the program cuts at is one pass, shallowest first, the cuts of a pass in program
// order, and a straight traverse (a rapid, not cut, not offset) from where one run of cuts
// stops to where the next one starts. G0 moves are traverses. A feed move whose Z changes
// along it (a ramp, a helix) is an entry move: taped as a traverse, not cut, and counted in
// a warning, as are feed moves at other depths than --cut-z (which keeps one pass) and feed
// moves before the first Z word of a program with Z. Without any Z word every feed move
// cuts, in one pass. Z-only moves (plunges, retracts) are skipped. The machine starts at
// (0, 0); after the last pass a traverse goes to where the program ends. Words after the
// end of the program (M2/M30) are ignored with a warning, as LinuxCNC does.
#include <algorithm>
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

std::string fmt_mm(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.4g", v);
  return buf;
}

std::string lower(std::string s) {
  for (char& c : s) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return s;
}

// LinuxCNC's O-word keywords: what they are, for the refusal.
const char* o_word_kind(const std::string& keyword) {
  static const std::map<std::string, const char*> kinds = {
      {"sub", "a subroutine"},       {"endsub", "a subroutine"}, {"call", "a subroutine call"},
      {"return", "a subroutine"},    {"if", "a condition"},      {"elseif", "a condition"},
      {"else", "a condition"},       {"endif", "a condition"},   {"while", "a loop"},
      {"endwhile", "a loop"},        {"do", "a loop"},           {"repeat", "a loop"},
      {"endrepeat", "a loop"},       {"break", "a loop"},        {"continue", "a loop"}};
  const auto it = kinds.find(keyword);
  return it == kinds.end() ? nullptr : it->second;
}

// Splits one line into words, dropping comments. Throws on malformed text, and on what a
// CAM post may write that is not a word address program (parameters, expressions, O-word
// control flow), with the reason.
std::vector<Word> words_of(const std::string& raw, const std::string& file, int line) {
  std::vector<Word> words;
  size_t i = 0;
  const size_t n = raw.size();
  const auto fail = [&](const std::string& what) { throw InputError(file, line, what); };
  while (i < n) {
    const char ch = raw[i];
    if (ch == ';') break;
    if (ch == '(') {
      const size_t close = raw.find(')', i);
      if (close == std::string::npos) fail("comment '(' is not closed");
      i = close + 1;
      continue;
    }
    if (std::isspace(static_cast<unsigned char>(ch)) || ch == '%') {
      ++i;
      continue;
    }
    if (ch == '#')
      fail("parameter '" + raw.substr(i, std::min<size_t>(n - i, 24)) +
           "': parameters (#) are not supported: the first stage reads plain numbers; set the "
           "post to write numbers, not variables");
    if (ch == '[')
      fail("expression '[' at column " + std::to_string(i + 1) +
           ": expressions are not supported: the first stage reads plain numbers; set the post "
           "to write numbers");
    if (!std::isalpha(static_cast<unsigned char>(ch)))
      fail(std::string("unexpected character '") + ch + "' at column " + std::to_string(i + 1));
    const char letter = static_cast<char>(std::toupper(static_cast<unsigned char>(ch)));
    size_t j = i + 1;
    while (j < n && std::isspace(static_cast<unsigned char>(raw[j]))) ++j;
    if (letter == 'O' && j < n && raw[j] == '<')  // o<name> sub / call: a named subroutine
      fail("O-word '" + raw.substr(i, std::min<size_t>(n - i, 32)) +
           "' (a named subroutine) is not supported: the first stage reads a program without "
           "subroutines, loops or conditions; set the post to write them out");
    const size_t start = j;
    if (j < n && (raw[j] == '+' || raw[j] == '-')) ++j;
    while (j < n && (std::isdigit(static_cast<unsigned char>(raw[j])) || raw[j] == '.')) ++j;
    const std::string num = raw.substr(start, j - start);
    if (j < n && (raw[j] == '#' || raw[j] == '['))
      fail(std::string("word ") + letter + " at column " + std::to_string(i + 1) + " takes " +
           (raw[j] == '#' ? "a parameter" : "an expression") +
           ": parameters and expressions are not supported: the first stage reads plain "
           "numbers; set the post to write numbers, not variables");
    char* end = nullptr;
    const double v = std::strtod(num.c_str(), &end);
    if (num.empty() || end != num.c_str() + num.size() || !std::isfinite(v))
      fail(std::string("word ") + letter + " needs a number at column " + std::to_string(i + 1));
    if (letter == 'O') {
      // O<n> alone is a program number; O<n> <keyword> is LinuxCNC control flow.
      size_t k = j;
      while (k < n && std::isspace(static_cast<unsigned char>(raw[k]))) ++k;
      size_t e = k;
      while (e < n && std::isalpha(static_cast<unsigned char>(raw[e]))) ++e;
      const std::string keyword = lower(raw.substr(k, e - k));
      if (const char* kind = o_word_kind(keyword))
        fail("O-word '" + raw.substr(i, e - i) + "' (" + kind +
             ") is not supported: the first stage reads a program without subroutines, loops "
             "or conditions; set the post to write them out");
    }
    words.push_back({letter, v, std::string(1, letter) + num});
    i = j;
  }
  return words;
}

// A '%' line marks the start or end of a program and holds nothing else (a comment at
// most). Posts that write a controller's header after it ("% vfd enable") are refused here
// with that reason, before the text is taken for words.
void check_percent_line(const std::string& raw, const std::string& file, int line) {
  size_t i = 0;
  while (i < raw.size() && std::isspace(static_cast<unsigned char>(raw[i]))) ++i;
  if (i >= raw.size() || raw[i] != '%') return;
  size_t k = i + 1;
  while (k < raw.size() && std::isspace(static_cast<unsigned char>(raw[k]))) ++k;
  if (k >= raw.size() || raw[k] == '(' || raw[k] == ';') return;
  size_t e = raw.find_last_not_of(" \t\r");
  const std::string text = raw.substr(k, e + 1 - k);
  throw InputError(file, line,
                   "'%' line with text ('% " + text +
                       "'): a '%' line marks the start or end of the program and holds "
                       "nothing else; this looks like a controller's header from the post: "
                       "remove it or make it a comment: (" + text + ")");
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

// One XY move of the program, in mm, with the Z at its start and end (NaN: no Z yet).
struct XyMove {
  Segment seg;
  Vec2 from, to;
  int line = 0;
  std::string kind;  // "G0", "G1", "G2", "G3"
  bool feed = false;  // G1/G2/G3
  double z0 = 0.0, z1 = 0.0;
};

// Depths closer than this are one depth (a Z written in inch and scaled, or rounded).
constexpr double kSameDepthMm = 1e-6;

// Counts of the feed moves taped as traverses, by reason, with the first line of each.
struct TraverseCount {
  int count = 0;
  int first_line = 0;
  void add(int line) {
    if (count++ == 0) first_line = line;
  }
  std::string text(const std::string& what) const {
    return std::to_string(count) + " " + what + " (first on line " + std::to_string(first_line) + ")";
  }
};

}  // namespace

Contour parse_gcode(const std::string& text, const std::string& file, double cut_z_mm) {
  IgnoredWords ignored;
  constexpr double kNoZ = std::numeric_limits<double>::quiet_NaN();
  double z = kNoZ;  // modal Z, mm (NaN: not known yet)
  bool has_z = false;
  std::vector<XyMove> moves;
  std::istringstream in(text);
  std::string raw;
  int line = 0;
  int motion = -1;  // modal G0..G3, none yet
  bool absolute = true;
  bool centre_absolute = false;  // G90.1: I/J absolute (G91.1, the default: from the start)
  double scale = 1.0;            // mm per program unit
  Vec2 cur{0.0, 0.0};
  int end_line = 0;              // line of M2/M30
  int lines_after_end = 0, first_after_end = 0;
  while (std::getline(in, raw)) {
    ++line;
    if (end_line) {
      // LinuxCNC ignores everything after the end of the program: so here, with a warning
      // (a '%' line, which closes a program, and blank lines are not counted).
      const auto first = raw.find_first_not_of(" \t\r");
      if (first != std::string::npos && raw[first] != '%') {
        if (lines_after_end++ == 0) first_after_end = line;
      }
      continue;
    }
    check_percent_line(raw, file, line);
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
    bool ends = false;
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
          } else if (std::fabs(g - 91.1) < 1e-9) {
            centre_absolute = false;
          } else if (std::fabs(g - 90.1) < 1e-9) {
            centre_absolute = true;
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
            fail(w.text + ": only the XY plane (G17) is supported, and " + w.text +
                 " switches to the " + (g == 18 ? "XZ" : "YZ") +
                 " plane, most likely for a vertical lead-in or lead-out arc of the post: turn "
                 "vertical lead-ins off (Fusion 360: Linking, Lead-in and Lead-out, 'Vertical "
                 "lead-in radius' and 'Vertical lead-out radius' 0), or let the post write XZ/YZ "
                 "arcs as lines (a Fusion post: allowedCircularPlanes = 1 << PLANE_XY)");
          } else if (g == 93) {
            // .nc names both: a contour to cut, and a tape `ncinterp tape` wrote (G93).
            fail("unsupported code " + w.text + " (inverse-time feed): this is a tape, not a "
                 "contour; a contour is expected here (a tape is played by play, check, cosim)");
          } else if (g >= 73 && g <= 89) {
            fail("unsupported code " + w.text + " (a canned cycle: drilling, boring or tapping): "
                 "a 2-D contour has no drilling; post the drilling operations to a file of their own");
          } else {
            fail("unsupported code " + w.text);
          }
          break;
        }
        case 'M': {
          const double m = w.value;
          if (m == 2 || m == 30) ends = true;
          else if (m == 0 || m == 1 || m == 3 || m == 4 || m == 5 || m == 6 || m == 7 ||
                   m == 8 || m == 9)
            ignored.note(word_kind(w), line);  // stops, spindle, tool change, coolant
          else if (m == 98 || m == 99)
            fail("unsupported code " + w.text + " (" + (m == 98 ? "subprogram call" : "subprogram end") +
                 "): the first stage reads a program without subprograms; set the post to "
                 "write them out (Fusion 360: post property 'Use subprograms' off)");
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
      has_z = true;
    }
    const bool has_xy = axis.count('X') || axis.count('Y');
    const bool has_arc_words = axis.count('I') || axis.count('J') || axis.count('R');
    if (has_xy || has_arc_words) {
      if (motion < 0) throw InputError(file, line, "move without a motion code (G0/G1/G2/G3)");
      Vec2 to = cur;
      if (axis.count('X')) to.x = (absolute ? 0.0 : cur.x) + scale * axis['X'];
      if (axis.count('Y')) to.y = (absolute ? 0.0 : cur.y) + scale * axis['Y'];
      XyMove mv;
      mv.from = cur;
      mv.to = to;
      mv.line = line;
      mv.feed = motion != 0;
      mv.z0 = z_before;
      mv.z1 = z;
      bool keep = true;
      if (motion <= 1) {
        if (has_arc_words) throw InputError(file, line, "I/J/R in a straight move (G0/G1)");
        keep = norm(to - cur) != 0.0;  // a move to where we are: nothing to cut
        mv.seg = Segment::line(cur, to);
        mv.kind = motion == 0 ? "G0" : "G1";
      } else {
        const bool ccw = motion == 3;
        mv.kind = ccw ? "G3" : "G2";
        Vec2 centre;
        if (axis.count('R')) {
          if (axis.count('I') || axis.count('J'))
            throw InputError(file, line, "arc with both R and I/J");
          if (norm(to - cur) == 0.0)
            throw InputError(file, line, "full circle with R: give the centre with I/J");
          // R is rounded as the post writes it: an R up to kArcEndTolerance short of half
          // the chord is the half circle (docs/first-stage.md 1.3).
          const double r = scale * axis['R'];
          const double half = 0.5 * norm(to - cur);
          const double shortfall = half - std::fabs(r);
          if (shortfall > kArcEndTolerance)
            throw InputError(file, line,
                             "arc radius R" + fmt(axis['R']) + " is " + fmt_mm(shortfall) +
                                 " mm shorter than half the distance to the end point (" +
                                 fmt_mm(half) + " mm; tolerance " + fmt(kArcEndTolerance) + " mm)");
          arc_centre_from_radius(cur, to, std::copysign(std::max(std::fabs(r), half), r), ccw, &centre);
        } else {
          if (!axis.count('I') && !axis.count('J'))
            throw InputError(file, line, "arc without a centre (I/J) or radius (R)");
          const Vec2 ij = scale * Vec2{axis.count('I') ? axis['I'] : 0.0, axis.count('J') ? axis['J'] : 0.0};
          centre = centre_absolute ? ij : cur + ij;
          if (norm(cur - centre) == 0.0) throw InputError(file, line, "arc of zero radius");
          const double off = arc_radius_mismatch(cur, to, centre);
          if (off > kArcEndTolerance)
            throw InputError(file, line, "arc end is " + fmt(off) +
                                             " mm off the circle about I/J (tolerance " +
                                             fmt(kArcEndTolerance) + " mm)");
        }
        mv.seg = arc_through(cur, to, centre, ccw);
      }
      if (keep) moves.push_back(mv);
      cur = to;
    }
    if (ends) end_line = line;
  }
  if (moves.empty()) throw InputError(file, line, "no XY motion in the program");

  // What each XY move is: a traverse, or a cut at a depth.
  TraverseCount ramps, before_z, other_depth;
  std::vector<double> depth(moves.size(), kNoZ);  // NaN: a traverse
  std::vector<bool> cuts(moves.size(), false);
  std::vector<double> depths;  // the cutting depths, distinct
  for (size_t i = 0; i < moves.size(); ++i) {
    const XyMove& m = moves[i];
    if (!m.feed) continue;
    if (!has_z) {
      cuts[i] = true;
      continue;
    }
    if (std::isnan(m.z0) || std::isnan(m.z1)) {
      before_z.add(m.line);
      continue;
    }
    if (std::fabs(m.z1 - m.z0) > kSameDepthMm) {
      ramps.add(m.line);
      continue;
    }
    cuts[i] = true;
    depth[i] = m.z1;
    if (std::none_of(depths.begin(), depths.end(), [&](double d) { return std::fabs(d - m.z1) <= kSameDepthMm; }))
      depths.push_back(m.z1);
  }
  std::sort(depths.begin(), depths.end(), std::greater<double>());  // shallowest first
  const auto depth_list = [&depths] {
    std::string s;
    for (double d : depths) s += (s.empty() ? "Z" : ", Z") + fmt(d);
    return s;
  };
  if (has_z && !std::isnan(cut_z_mm)) {
    const auto it = std::find_if(depths.begin(), depths.end(),
                                 [&](double d) { return std::fabs(d - cut_z_mm) <= kSameDepthMm; });
    if (it == depths.end())
      throw InputError(file, 0, "no XY feed move at the cutting depth Z" + fmt(cut_z_mm) + " mm" +
                                    (depths.empty() ? std::string()
                                                    : " (--cut-z): the program cuts at " + depth_list() + " mm"));
    const double keep = *it;
    for (size_t i = 0; i < moves.size(); ++i)
      if (cuts[i] && std::fabs(depth[i] - keep) > kSameDepthMm) {
        cuts[i] = false;
        other_depth.add(moves[i].line);
      }
    depths = {keep};
  }
  if (has_z && depths.empty())
    throw InputError(file, 0, "no XY feed move at a constant Z: nothing to cut (ramps and helices "
                              "are entry moves, taped as traverses)");
  if (!has_z && std::none_of(cuts.begin(), cuts.end(), [](bool c) { return c; }))
    throw InputError(file, 0, "no feed move (G1/G2/G3) in XY: nothing to cut, every move is a traverse (G0)");
  if (!has_z) depths = {kNoZ};

  // The passes: per depth, the runs of consecutive cuts at it, a traverse before each run.
  Contour contour;
  contour.file = file;
  Vec2 at{0.0, 0.0};
  // `to`: the end as the program wrote it (an arc's computed end may differ in the last bit).
  const auto add = [&contour, &at](Segment seg, Vec2 to, int src_line, const std::string& name) {
    seg.source_line = src_line;
    seg.source_index = static_cast<int>(contour.element_names.size());
    contour.element_names.push_back(name);
    at = to;
    contour.segments.push_back(seg);
  };
  const auto traverse = [&](Vec2 to, int src_line, const std::string& name) {
    if (norm(to - at) == 0.0) return;
    Segment t = Segment::line(at, to);
    t.rapid = true;
    add(t, to, src_line, name);
  };
  for (double d : depths) {
    CutPass pass{d, static_cast<int>(contour.element_names.size()), 0};
    const auto cut_here = [&](size_t i) {
      return cuts[i] && (std::isnan(d) || std::fabs(depth[i] - d) <= kSameDepthMm);
    };
    for (size_t i = 0; i < moves.size();) {
      if (!cut_here(i)) {
        ++i;
        continue;
      }
      traverse(moves[i].from, moves[i].line, "traverse to line " + std::to_string(moves[i].line));
      for (; i < moves.size() && cut_here(i); ++i)
        add(moves[i].seg, moves[i].to, moves[i].line,
            "line " + std::to_string(moves[i].line) + " (" + moves[i].kind + ")");
    }
    pass.end_element = static_cast<int>(contour.element_names.size());
    contour.passes.push_back(pass);
  }
  traverse(cur, moves.back().line, "traverse to the end (line " + std::to_string(moves.back().line) + ")");
  contour.passes.back().end_element = static_cast<int>(contour.element_names.size());

  contour.warnings = ignored.warnings(file);
  if (ramps.count + before_z.count + other_depth.count > 0) {
    std::string w;
    const auto part = [&w](const TraverseCount& c, const std::string& what) {
      if (c.count) w += (w.empty() ? "" : ", ") + c.text(what);
    };
    part(ramps, "ramps or helices (Z changes along the move: entry moves)");
    part(other_depth, "at other depths than --cut-z " + fmt(cut_z_mm));
    part(before_z, "before the first Z word");
    const int total = ramps.count + before_z.count + other_depth.count;
    contour.warnings.push_back(file + ": warning: " + std::to_string(total) + " feed move" +
                               (total == 1 ? "" : "s") + " (G1/G2/G3) taped as traverses (G00), not cut: " + w);
  }
  if (lines_after_end > 0)
    contour.warnings.push_back(file + ": warning: " + std::to_string(lines_after_end) + " line" +
                               (lines_after_end == 1 ? "" : "s") + " after the end of the program (M2/M30 on line " +
                               std::to_string(end_line) + ") ignored, as LinuxCNC does (first: line " +
                               std::to_string(first_after_end) + ")");
  return contour;
}

}  // namespace ncinterp::firststage
