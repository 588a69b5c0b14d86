// The first stage pipeline (see firststage.h).
#include "firststage.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <optional>
#include <stdexcept>
#include <string>

#include "chords/chord_planner.h"
#include "inputs/input_error.h"
#include "measure/self_intersection.h"
#include "offset/cutter_offset.h"
#include "output/quadrant_arcs.h"

namespace ncinterp::firststage {
namespace {

unsigned frac_digits_of(double blu_mm) {
  for (unsigned k = 0; k <= 6; ++k)
    if (std::fabs(blu_mm * std::pow(10.0, k) - 1.0) < 1e-9) return k;
  throw std::invalid_argument("--blu must be 1, 0.1, 0.01, ... 0.000001 mm (the tape writes decimal digits)");
}

// Splits every line longer than the register into equal parts (rounded intermediate
// points: at most half a BLU off the line in each axis).
std::vector<Move> split_long_lines(GridPoint start, const std::vector<Move>& moves, int64_t max_inc) {
  std::vector<Move> out;
  out.reserve(moves.size());
  GridPoint cur = start;
  for (const Move& m : moves) {
    const int64_t dx = m.to.x - cur.x, dy = m.to.y - cur.y;
    const int64_t big = std::max(std::llabs(dx), std::llabs(dy));
    if (m.kind == MoveKind::kLine && big > max_inc) {
      const int64_t parts = (big + max_inc - 1) / max_inc;
      for (int64_t k = 1; k < parts; ++k) {
        Move piece = m;
        piece.to = {cur.x + static_cast<int64_t>(std::llround(static_cast<double>(dx) * k / parts)),
                    cur.y + static_cast<int64_t>(std::llround(static_cast<double>(dy) * k / parts))};
        out.push_back(piece);
      }
    }
    out.push_back(m);
    cur = m.to;
  }
  return out;
}

std::string fmt_mm(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%g", v);
  return buf;
}

// Every point of the contour (and the cutter about it) must be a position the interpolator's
// 32-bit position counters hold, in BLU. Checked before anything is scaled or allocated:
// a coordinate of 1e30 would overflow the int64 grid, a 1e9 mm line would be split into
// millions of blocks first. Names the input line.
void check_position_range(const Contour& contour, const FirstStageOptions& o) {
  const double limit_mm = static_cast<double>((int64_t{1} << (kPositionBits - 1)) - 1) * o.blu_mm;
  const auto check = [&](Vec2 p, int line) {
    const double reach = std::max(std::fabs(p.x), std::fabs(p.y)) + o.cutter_radius_mm;
    if (!(reach <= limit_mm)) {
      char what[200];
      std::snprintf(what, sizeof what,
                    "point (%g, %g) mm is outside the interpolator's position range +-%.6g mm "
                    "(%d-bit counters at BLU %g mm)",
                    p.x, p.y, limit_mm, kPositionBits, o.blu_mm);
      throw InputError(contour.file, line, what);
    }
  };
  check(contour.origin, contour.segments.empty() ? 0 : contour.segments.front().source_line);
  for (const Segment& s : contour.segments) {
    check(s.start(), s.source_line);
    check(s.end(), s.source_line);
  }
}

std::string element_name(const Contour& c, const Move& m) {
  return m.element >= 0 && m.element < static_cast<int>(c.element_names.size())
             ? c.element_names[m.element]
             : std::string("a join of the offset");
}

// The moves with those of every pass but `pass` turned into traverses: the passes of a
// G-code program are cut one after the other (at their own depths), so only the moves of
// one pass can cross each other. A move belongs to the pass of its element; the offset's
// joins (element -1) to the pass of the move before them.
std::vector<Move> pass_moves(const Contour& c, const std::vector<Move>& moves, size_t pass) {
  std::vector<Move> out = moves;
  if (c.passes.size() < 2) return out;
  size_t p = 0;
  for (Move& m : out) {
    if (m.element >= 0) {
      p = 0;
      while (p + 1 < c.passes.size() && m.element >= c.passes[p].end_element) ++p;
    }
    if (p != pass) m.rapid = true;
  }
  return out;
}

// Pairs of input elements that touch where the contour comes back to a point: a CAM
// program's lead-in ends where its lead-out starts, both tangent to the profile there, and
// the chords of such paths cross within a chord's length of the point, where the path
// touches itself without crossing over. Crossings of two such elements are not reported.
class Touching {
 public:
  Touching(const Contour& c, double to_blu) {
    using P = std::pair<int64_t, int64_t>;
    const auto grid = [to_blu](Vec2 v) {
      const GridPoint g = round_to_grid(to_blu * v);
      return P{g.x, g.y};
    };
    ends_.assign(c.element_names.size(), {P{INT64_MIN, INT64_MIN}, P{INT64_MIN, INT64_MIN}});
    std::vector<bool> seen(c.element_names.size(), false);
    std::vector<P> visits;
    for (const Segment& s : c.segments) {
      visits.push_back(grid(s.start()));
      if (s.source_index < 0 || s.source_index >= static_cast<int>(ends_.size())) continue;
      if (!seen[s.source_index]) ends_[s.source_index].first = grid(s.start());
      seen[s.source_index] = true;
      ends_[s.source_index].second = grid(s.end());
    }
    std::sort(visits.begin(), visits.end());
    for (size_t i = 1; i < visits.size(); ++i)
      if (visits[i] == visits[i - 1]) twice_.push_back(visits[i]);
  }
  bool operator()(int ea, int eb) const {
    if (ea < 0 || eb < 0 || ea == eb || ea >= static_cast<int>(ends_.size()) || eb >= static_cast<int>(ends_.size()))
      return false;
    for (const auto& p : {ends_[ea].first, ends_[ea].second})
      if ((p == ends_[eb].first || p == ends_[eb].second) &&
          std::binary_search(twice_.begin(), twice_.end(), p))
        return true;
    return false;
  }

 private:
  std::vector<std::pair<std::pair<int64_t, int64_t>, std::pair<int64_t, int64_t>>> ends_;  // per element
  std::vector<std::pair<int64_t, int64_t>> twice_;  // points the contour starts a segment at twice
};

std::optional<SelfCrossing> crossing_in_a_pass(const Contour& c, const FirstStageOptions& o, GridPoint start,
                                               const std::vector<Move>& moves, std::vector<Move>* in_pass) {
  const Touching touching(c, 1.0 / o.blu_mm);
  const auto ignore = [&](int a, int b) { return touching(moves[a].element, moves[b].element); };
  for (size_t p = 0; p < std::max<size_t>(1, c.passes.size()); ++p) {
    *in_pass = pass_moves(c, moves, p);
    if (const auto x = find_self_crossing(start, *in_pass, ignore)) return x;
  }
  return std::nullopt;
}

// A crossing of the contour's own path, else of the cutter path, within one pass: a
// warning, not an error (docs/first-stage.md, "Self-crossing paths").
void warn_self_crossing(const Contour& contour, const FirstStageOptions& o, FirstStageResult& res) {
  const auto where = [&](const SelfCrossing& x) {
    char buf[96];
    std::snprintf(buf, sizeof buf, "(%.3f, %.3f) mm", x.at.x * o.blu_mm, x.at.y * o.blu_mm);
    return std::string(buf);
  };
  std::vector<Move> in_pass;
  if (const auto x = crossing_in_a_pass(contour, o, res.contour_start, res.contour_moves, &in_pass)) {
    res.warnings.push_back(contour.file + ": warning: the contour crosses itself at " + where(*x) +
                           " (" + element_name(contour, res.contour_moves[x->move_a]) + " and " +
                           element_name(contour, res.contour_moves[x->move_b]) +
                           "): the tape cuts it as drawn");
    return;
  }
  if (o.cutter_radius_mm <= 0) return;
  if (const auto x = crossing_in_a_pass(contour, o, res.start, res.moves, &in_pass))
    res.warnings.push_back(contour.file + ": warning: the cutter path (radius " + fmt_mm(o.cutter_radius_mm) +
                           " mm) crosses itself at " + where(*x) + " (near " +
                           element_name(contour, res.moves[x->move_a]) +
                           "): a detail of the part is narrower than the cutter");
}

}  // namespace

tape::Format tape_format(const FirstStageOptions& options) {
  tape::Format f;
  f.frac_digits = frac_digits_of(options.blu_mm);
  f.feed_frac_digits = 3;
  f.inc_width = options.width;
  f.feed_width = options.feed_width;
  return f;
}

void validate_options(const FirstStageOptions& o) {
  if (o.method < 1 || o.method > 3) throw std::invalid_argument("--method must be 1, 2 or 3");
  frac_digits_of(o.blu_mm);
  if (o.width < 2 || o.width > 32) throw std::invalid_argument("--width must be 2..32 bits");
  if (!(o.tol_mm > 0)) throw std::invalid_argument("--tol must be > 0");
  if (!(o.feed_mm_min > 0)) throw std::invalid_argument("--feed must be > 0");
  if (!(o.budget_blu >= 0)) throw std::invalid_argument("--budget must be >= 0");
  if (!(o.cutter_radius_mm >= 0)) throw std::invalid_argument("--cutter-radius must be >= 0");
  if (o.cutter_radius_mm > 0 && o.arcs_circle)
    throw std::invalid_argument("the cutter offset works on chords: use --arcs chords with --cutter-radius");
  const double reserve = o.budget_blu + (o.cutter_radius_mm > 0 ? 1.0 : 0.0);
  if (o.tol_mm / o.blu_mm - reserve < 1.0)
    throw std::invalid_argument(
        "--tol leaves less than 1 BLU for the chords after the interpolator's budget" +
        std::string(o.cutter_radius_mm > 0 ? " and the offset rounding (1 BLU)" : "") +
        ": raise --tol or use a finer --blu");
}

uint64_t inverse_time_feed(double length_mm, double feed_mm_min, const tape::Format& format) {
  const double scale = std::pow(10.0, format.feed_frac_digits);
  const double f = std::floor(feed_mm_min / length_mm * scale * (1.0 + 1e-15));
  const uint64_t register_max = (uint64_t{1} << format.feed_width) - 1;
  if (!(f < static_cast<double>(register_max))) return register_max;
  return f < 1.0 ? 1 : static_cast<uint64_t>(f);
}

double arc_feed_mm_min(double radius_mm, const FirstStageOptions& o) {
  if (!(o.accel_mm_s2 > 0)) return o.feed_mm_min;
  return std::min(o.feed_mm_min, 60.0 * std::sqrt(o.accel_mm_s2 * radius_mm));
}

double move_length_mm(GridPoint from, const Move& m, double blu_mm) {
  const Vec2 a = to_vec(from), b = to_vec(m.to);
  if (m.kind == MoveKind::kLine) return norm(b - a) * blu_mm;
  const Vec2 c = to_vec(m.centre);
  const Vec2 ra = a - c, rb = b - c;
  double sweep = std::atan2(cross(ra, rb), dot(ra, rb));
  if (m.kind == MoveKind::kArcCcw && sweep < 0) sweep += 2 * M_PI;
  if (m.kind == MoveKind::kArcCw && sweep > 0) sweep -= 2 * M_PI;
  if (sweep == 0.0 && norm(b - a) == 0.0) sweep = 2 * M_PI;
  return 0.5 * (norm(ra) + norm(rb)) * std::fabs(sweep) * blu_mm;
}

FirstStageResult run_first_stage(const Contour& contour, const FirstStageOptions& o) {
  validate_options(o);
  check_position_range(contour, o);
  const double to_blu = 1.0 / o.blu_mm;
  const int64_t max_inc = (int64_t{1} << o.width) - 1;
  FirstStageResult res;
  res.frac_digits = static_cast<int>(frac_digits_of(o.blu_mm));
  const bool offset = o.cutter_radius_mm > 0;
  const double delta_blu = o.tol_mm * to_blu - o.budget_blu - (offset ? 1.0 : 0.0);
  res.chord_delta_mm = delta_blu * o.blu_mm;
  std::vector<Segment> segs;
  segs.reserve(contour.segments.size());
  for (const Segment& s : contour.segments) {
    // A full circle no wider than delta' lies within delta' of its own start: its chords
    // would start and end at one point (nothing to cut). Refused with the reason, up front.
    if (!s.rapid && s.is_arc() && std::fabs(s.sweep()) > 2 * M_PI - 1e-9 && s.radius() * to_blu <= delta_blu)
      throw InputError(contour.file, s.source_line,
                       "full circle of radius " + fmt_mm(s.radius()) + " mm is within the tolerance (delta' " +
                           fmt_mm(delta_blu * o.blu_mm) + " mm) of its start: nothing to cut; use a smaller --tol");
    segs.push_back(s.scaled(to_blu));
  }
  res.chords_per_element.assign(contour.element_names.size(), 0);

  PlannerOptions popt;
  popt.method = o.method;
  popt.delta = delta_blu;
  popt.max_inc = max_inc;
  ChordPlanner planner(popt);
  res.start = res.contour_start = round_to_grid(to_blu * contour.origin);
  GridPoint cur = res.start;
  std::vector<ChordEnd> ends;
  const int n = static_cast<int>(segs.size());
  for (int i = 0; i < n;) {
    const Segment& first = segs[i];
    const GridPoint target = round_to_grid(first.end());
    if (first.rapid || first.kind() == SegmentKind::kLine) {
      // Straight segments are their own chord (split to the register width later).
      if (target != cur)
        res.contour_moves.push_back({MoveKind::kLine, target, {}, first.source_index, false, first.rapid});
      cur = target;
      ++i;
      continue;
    }
    if (o.arcs_circle && first.is_arc()) {
      const bool fits = quadrant_arcs(first, cur, max_inc, delta_blu, first.source_index, res.contour_moves);
      if (fits) {
        cur = res.contour_moves.back().to;
        ++i;
        continue;
      }
      // Radius too wide for the I/J registers: this arc is chorded like any curve.
    }
    // A span: i and the following segments joined smoothly (unless zones or arc blocks).
    int j = i + 1;
    while (j < n && !o.zones && smooth_joint(segs[j - 1], segs[j]) &&
           segs[j].kind() != SegmentKind::kLine && !(o.arcs_circle && segs[j].is_arc()))
      ++j;
    const Span span(&segs[i], j - i);
    const GridPoint end = round_to_grid(segs[j - 1].end());
    ends.clear();
    try {
      planner.plan(span, cur, end, ends);
    } catch (const std::runtime_error& e) {
      throw InputError(contour.file, first.source_line, e.what());
    }
    for (const ChordEnd& ce : ends) {
      const int element = segs[i + ce.segment].source_index;
      res.contour_moves.push_back({MoveKind::kLine, ce.p, {}, element, true, false});
      ++res.chords_per_element[element];
    }
    cur = end;
    i = j;
  }
  res.planner = planner.stats();
  if (std::none_of(res.contour_moves.begin(), res.contour_moves.end(), [](const Move& m) { return !m.rapid; }))
    throw InputError(contour.file, 0,
                     "no cutting move of 1 BLU or more on the grid (BLU " + fmt_mm(o.blu_mm) +
                         " mm): the contour is too short to cut");
  if (offset) {
    CutterOffsetOptions oo;
    oo.radius = o.cutter_radius_mm * to_blu;
    oo.left = o.side_left;
    try {
      res.moves = offset_moves(res.start, res.contour_moves, oo, &res.start);
    } catch (const std::runtime_error& e) {
      throw InputError(contour.file, 0, e.what());
    }
  } else {
    res.moves = res.contour_moves;
  }
  res.moves = split_long_lines(res.start, res.moves, max_inc);
  warn_self_crossing(contour, o, res);
  return res;
}

namespace {

// --tool: every run of cuts (blocks other than G00) gets M03 with its first block, as it
// starts, and M05 with its last, as its motion ends; a run of one block, which can carry
// one M word only, gets its M05 in a still block after it, with the same N (so the motion
// blocks keep their numbers). Both act at rest (exact stop), and the traverses between
// runs play with the tool off.
void switch_tool_for_cuts(tape::Program& prog, double pierce_delay_s, const tape::Format& format) {
  std::vector<tape::Block> out;
  const std::vector<tape::Block>& in = prog.blocks;
  for (size_t k = 0; k < in.size(); ++k) {
    tape::Block b = in[k];
    const bool cut = !tape::is_rapid(b.motion);
    const bool first = cut && (k == 0 || tape::is_rapid(in[k - 1].motion));
    const bool last = cut && (k + 1 == in.size() || tape::is_rapid(in[k + 1].motion));
    if (first && pierce_delay_s > 0) {
      // The pierce: the tool on at rest for the delay, a G01 of length 0 lasting 1/F (the
      // feed rounded down: never shorter), with the cut's N.
      tape::Block pierce{b.n, tape::Motion::kLine};
      pierce.feed = inverse_time_feed(1.0, 60.0 / pierce_delay_s, format);
      pierce.tool_on = true;
      out.push_back(pierce);
    }
    b.tool_on = first && pierce_delay_s <= 0;
    b.tool_off = last && !b.tool_on;
    out.push_back(b);
    if (first && last && b.tool_on) {
      tape::Block off{b.n, tape::Motion::kRapid};
      off.still = off.tool_off = true;
      out.push_back(off);
    }
  }
  prog.blocks = std::move(out);
}

}  // namespace

tape::Program make_program(const FirstStageResult& r, const FirstStageOptions& o) {
  tape::Program prog;
  prog.blocks.reserve(r.moves.size());
  const tape::Format format = tape_format(o);
  GridPoint cur = r.start;
  uint32_t n = 0;
  for (const Move& m : r.moves) {
    tape::Block b;
    b.n = ++n;
    b.motion = m.kind == MoveKind::kLine    ? (m.rapid ? tape::Motion::kRapid : tape::Motion::kLine)
               : m.kind == MoveKind::kArcCw ? tape::Motion::kArcCw
                                            : tape::Motion::kArcCcw;
    b.dx = m.to.x - cur.x;
    b.dy = m.to.y - cur.y;
    if (m.kind != MoveKind::kLine) {
      b.i = m.centre.x - cur.x;
      b.j = m.centre.y - cur.y;
    }
    // A traverse (G00) has no F: it plays at the machine's rapid rate. An arc plays at most
    // at sqrt(A R) under an acceleration limit.
    const double feed = m.kind == MoveKind::kLine ? o.feed_mm_min
                                                  : arc_feed_mm_min(std::hypot(b.i, b.j) * o.blu_mm, o);
    if (!m.rapid) b.feed = inverse_time_feed(move_length_mm(cur, m, o.blu_mm), feed, format);
    prog.blocks.push_back(b);
    cur = m.to;
  }
  if (o.tool) switch_tool_for_cuts(prog, o.pierce_delay_s, format);
  return prog;
}

}  // namespace ncinterp::firststage
