// Quadrant arc blocks (see quadrant_arcs.h).
#include "output/quadrant_arcs.h"

#include <cmath>

namespace ncinterp::firststage {

bool quadrant_arcs(const Segment& arc, GridPoint start, int64_t max_inc, double max_dev,
                   int element, std::vector<Move>& out) {
  const Vec2 c = arc.centre();
  const double r = arc.radius();
  const bool ccw = arc.sweep() > 0;
  if (r < 2.0 || r + 2.0 > static_cast<double>(max_inc)) return false;
  const GridPoint end = round_to_grid(arc.end());
  const bool full = std::fabs(arc.sweep()) > 1.5 * M_PI && start == end;
  // Centre: the grid point near c with the smallest start/end radius difference.
  const GridPoint c0 = round_to_grid(c);
  GridPoint cq = c0;
  double best = INFINITY;
  for (int dy = -2; dy <= 2; ++dy)
    for (int dx = -2; dx <= 2; ++dx) {
      const GridPoint g{c0.x + dx, c0.y + dy};
      const double rs = norm(to_vec(start) - to_vec(g)), re = norm(to_vec(end) - to_vec(g));
      const double score = std::fabs(rs - re) + 1e-3 * norm(to_vec(g) - c);
      if (score < best) best = score, cq = g;
    }
  const Vec2 cv = to_vec(cq);
  const double rs = norm(to_vec(start) - cv), re = norm(to_vec(end) - cv);
  const double radius = 0.5 * (rs + re);
  const int64_t rq = std::llround(radius);
  // How far the blocks' circle is from the true one (centre shift + radius change + rounding).
  if (norm(cv - c) + std::fabs(radius - r) + 0.5 * std::fabs(rs - re) + 0.5 > max_dev) return false;
  // Angles from the grid points themselves; boundaries strictly inside the sweep.
  const double th_s = std::atan2(start.y - cq.y, start.x - cq.x);
  double sweep = std::atan2(end.y - cq.y, end.x - cq.x) - th_s;
  if (full) sweep = ccw ? 2 * M_PI : -2 * M_PI;
  else if (ccw) sweep = std::fmod(sweep + 4 * M_PI, 2 * M_PI);
  else sweep = -std::fmod(-sweep + 4 * M_PI, 2 * M_PI);
  std::vector<Move> pieces;
  const MoveKind kind = ccw ? MoveKind::kArcCcw : MoveKind::kArcCw;
  const double q = M_PI / 2;
  // Boundary k (multiples of 90 degrees) after th_s in the direction of travel.
  double k = ccw ? std::floor(th_s / q + 1e-12) + 1 : std::ceil(th_s / q - 1e-12) - 1;
  for (;; k += ccw ? 1 : -1) {
    const double ang = k * q;
    if (ccw ? ang >= th_s + sweep : ang <= th_s + sweep) break;
    const int quarter = static_cast<int>(((static_cast<long>(k) % 4) + 4) % 4);
    const GridPoint b = quarter == 0   ? GridPoint{cq.x + rq, cq.y}
                        : quarter == 1 ? GridPoint{cq.x, cq.y + rq}
                        : quarter == 2 ? GridPoint{cq.x - rq, cq.y}
                                       : GridPoint{cq.x, cq.y - rq};
    pieces.push_back({kind, b, cq, element, false, false});
  }
  if (pieces.empty() || pieces.back().to != end) pieces.push_back({kind, end, cq, element, false, false});
  // Check every block: radius change <= 1 BLU, registers.
  GridPoint cur = start;
  for (const Move& m : pieces) {
    const double r0 = norm(to_vec(cur) - cv), r1 = norm(to_vec(m.to) - cv);
    if (std::fabs(r1 - r0) > 1.0 || m.to == cur) return false;
    if (std::llabs(m.to.x - cur.x) > max_inc || std::llabs(m.to.y - cur.y) > max_inc ||
        std::llabs(cq.x - cur.x) > max_inc || std::llabs(cq.y - cur.y) > max_inc)
      return false;
    cur = m.to;
  }
  out.insert(out.end(), pieces.begin(), pieces.end());
  return true;
}

}  // namespace ncinterp::firststage
