// Cutter-centre offset of chord chains (see cutter_offset.h).
#include "offset/cutter_offset.h"

#include <cmath>
#include <optional>
#include <stdexcept>

namespace ncinterp::firststage {
namespace {

struct OffsetLine {
  Vec2 p, d, n;     // a point of the chord, unit direction, unit normal toward the cutter
  int element = -1;
};

// Intersection of offset lines a and b (offset by R along their normals).
Vec2 intersect(const OffsetLine& a, const OffsetLine& b, double r) {
  const Vec2 pa = a.p + r * a.n, pb = b.p + r * b.n;
  const double den = cross(a.d, b.d);
  if (std::fabs(den) < 1e-12) return pb;  // parallel: they meet where b starts
  const double s = cross(pb - pa, b.d) / den;
  return pa + s * a.d;
}

// Vertices of the offset path between line a (ending at chord vertex v) and line b.
void corner(const OffsetLine& a, const OffsetLine& b, Vec2 v, double r, std::vector<Vec2>& out) {
  const double turn = std::atan2(cross(a.d, b.d), dot(a.d, b.d));
  // Convex: the path turns away from the cutter, i.e. opposite to the cutter's normal side.
  const double side = cross(a.d, a.n) > 0 ? 1.0 : -1.0;  // +1: cutter on the left
  const bool convex = side * turn < 0;
  if (!convex || std::fabs(turn) <= M_PI / 2 + 1e-12) {
    out.push_back(intersect(a, b, r));
    return;
  }
  const int pieces = static_cast<int>(std::ceil(std::fabs(turn) / (M_PI / 2) - 1e-12));
  const double phi = turn / pieces;
  const double th = std::atan2(a.n.y, a.n.x);
  const double reach = r / std::cos(0.5 * phi);
  for (int j = 0; j < pieces; ++j) {
    const double ang = th + (j + 0.5) * phi;
    out.push_back(v + reach * Vec2{std::cos(ang), std::sin(ang)});
  }
}

// Offsets one chain of chord vertices pts (pts.size() >= 2). Returns the offset vertices
// and, per vertex, the element of the chord it ends.
void offset_chain(const std::vector<Vec2>& pts, const std::vector<int>& elements, double r,
                  bool left, std::vector<Vec2>* out, std::vector<int>* out_elements, long* dropped) {
  const bool closed = pts.size() > 3 && norm(pts.front() - pts.back()) == 0.0;
  std::vector<OffsetLine> lines;
  std::vector<Vec2> ends;  // chord vertex at the end of each line
  for (size_t k = 0; k + 1 < pts.size(); ++k) {
    const Vec2 d = unit(pts[k + 1] - pts[k]);
    if (norm(d) == 0.0) continue;
    lines.push_back({pts[k], d, left ? perp(d) : -1.0 * perp(d), elements[k]});
    ends.push_back(pts[k + 1]);
  }
  // Drop lines whose trimmed offset reverses, until none does. A line is trimmed only at
  // concave joints (there its offset ends where the neighbour's begins); at a convex joint
  // it is extended, so it cannot reverse. An open chain's first (last) line starts (ends)
  // at the normal offset of the chain's end point; if that line reverses, the path must
  // not follow it back (it would pass nearer than R to the chord before it), so it is
  // dropped but kept as the chain's bound: the path then starts (ends) where the next
  // line's offset meets its offset, as at an inner concave joint.
  const double side = left ? 1.0 : -1.0;
  const auto concave = [&](const OffsetLine& a, const OffsetLine& b) {
    return side * std::atan2(cross(a.d, b.d), dot(a.d, b.d)) >= 0;
  };
  const Vec2 chain_start = pts.front();
  std::optional<OffsetLine> first_bound, last_bound;  // dropped terminal lines (open chains)
  const auto path_start = [&]() {
    return first_bound ? intersect(*first_bound, lines.front(), r) : chain_start + r * lines.front().n;
  };
  const auto path_end = [&]() {
    return last_bound ? intersect(lines.back(), *last_bound, r) : ends.back() + r * lines.back().n;
  };
  for (bool again = true; again && lines.size() >= 2;) {
    again = false;
    const size_t m = lines.size();
    for (size_t k = 0; k < m; ++k) {
      const bool has_prev = closed || k > 0, has_next = closed || k + 1 < m;
      if (closed && m <= 2) continue;
      const OffsetLine& b = lines[k];
      if (has_prev && !concave(lines[(k + m - 1) % m], b)) continue;
      if (has_next && !concave(b, lines[(k + 1) % m])) continue;
      const Vec2 s = has_prev ? intersect(lines[(k + m - 1) % m], b, r) : path_start();
      const Vec2 e = has_next ? intersect(b, lines[(k + 1) % m], r) : path_end();
      if (dot(e - s, b.d) < 0) {
        if (!has_prev && !first_bound) first_bound = b;
        if (!has_next && !last_bound) last_bound = b;
        lines.erase(lines.begin() + static_cast<long>(k));
        ends.erase(ends.begin() + static_cast<long>(k));
        if (dropped) ++*dropped;
        again = true;
        break;
      }
    }
  }
  const size_t m = lines.size();
  if (m == 0) return;
  // Start point.
  if (closed) {
    std::vector<Vec2> first;
    corner(lines[m - 1], lines[0], lines[0].p, r, first);
    out->push_back(first.back());
  } else {
    out->push_back(path_start());
  }
  for (size_t k = 0; k < m; ++k) {
    const bool last = k + 1 == m;
    std::vector<Vec2> vs;
    if (!last) {
      corner(lines[k], lines[k + 1], ends[k], r, vs);
    } else if (closed) {
      corner(lines[k], lines[0], ends[k], r, vs);
      // The path ends where it started: the last vertex of this corner.
    } else {
      vs.push_back(path_end());
    }
    for (const Vec2& v : vs) {
      out->push_back(v);
      out_elements->push_back(lines[k].element);
    }
  }
  if (closed) {
    // The closing corner's vertices were appended at the end; the path must end exactly
    // at its start, which is that corner's last vertex.
    out->back() = out->front();
  }
}

}  // namespace

std::vector<Move> offset_moves(GridPoint start, const std::vector<Move>& moves,
                               const CutterOffsetOptions& opt, GridPoint* new_start,
                               long* dropped) {
  std::vector<Move> out;
  out.reserve(moves.size() + 16);
  GridPoint cur = start;
  bool first_chain = true;
  size_t i = 0;
  *new_start = start;
  GridPoint out_cur = start;
  while (i < moves.size()) {
    if (moves[i].rapid) {
      // Aim the rapid at the start of the next offset chain (filled in below).
      out.push_back(moves[i]);
      cur = moves[i].to;
      out_cur = moves[i].to;
      ++i;
      first_chain = false;
      continue;
    }
    // A cutting chain: moves i..j-1.
    size_t j = i;
    std::vector<Vec2> pts{to_vec(cur)};
    std::vector<int> elements;
    while (j < moves.size() && !moves[j].rapid) {
      if (moves[j].kind != MoveKind::kLine)
        throw std::runtime_error("the cutter offset works on chords: use --arcs chords with --cutter-radius");
      pts.push_back(to_vec(moves[j].to));
      elements.push_back(moves[j].element);
      ++j;
    }
    std::vector<Vec2> verts;
    std::vector<int> vel;
    offset_chain(pts, elements, opt.radius, opt.left, &verts, &vel, dropped);
    if (!verts.empty()) {
      const GridPoint s = round_to_grid(verts[0]);
      if (first_chain && out.empty()) {
        *new_start = s;
      } else if (!out.empty() && out.back().rapid) {
        out.back().to = s;  // the rapid now ends at the offset start
      } else if (s != out_cur) {
        out.push_back({MoveKind::kLine, s, {}, -1, false, false});
      }
      out_cur = s;
      for (size_t k = 1; k < verts.size(); ++k) {
        const GridPoint g = round_to_grid(verts[k]);
        if (g == out_cur) continue;
        out.push_back({MoveKind::kLine, g, {}, vel[k - 1], true, false});
        out_cur = g;
      }
    }
    first_chain = false;
    cur = moves[j - 1].to;
    i = j;
  }
  return out;
}

}  // namespace ncinterp::firststage
