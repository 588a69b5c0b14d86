// Programmed path geometry (see programmed_path.h).
#include "programmed_path.h"

#include <algorithm>
#include <cmath>

#include "contour_distance.h"

namespace ncinterp::checker {

double ProgrammedBlock::sweep() const {
  const Vec2 a = to_vec(start) - centre, b = to_vec(end) - centre;
  double s = std::atan2(a.x * b.y - a.y * b.x, a.x * b.x + a.y * b.y);  // (-pi, pi]
  const bool ccw = tape.motion == tape::Motion::kArcCcw;
  if (start == end) return ccw ? 2 * M_PI : -2 * M_PI;
  if (ccw && s <= 0) s += 2 * M_PI;
  if (!ccw && s >= 0) s -= 2 * M_PI;
  return s;
}

double ProgrammedBlock::length() const {
  if (!is_arc()) return norm(to_vec(end) - to_vec(start));
  const double r0 = norm(to_vec(start) - centre), r1 = norm(to_vec(end) - centre);
  return 0.5 * (r0 + r1) * std::fabs(sweep());
}

Vec2 ProgrammedBlock::point_at(double s) const {
  const Vec2 a = to_vec(start), b = to_vec(end);
  if (!is_arc()) return a + s * (b - a);
  const Vec2 ra = a - centre;
  const double r0 = norm(ra), r1 = norm(b - centre);
  const double th = std::atan2(ra.y, ra.x) + s * sweep();
  const double r = r0 + s * (r1 - r0);
  return centre + r * Vec2{std::cos(th), std::sin(th)};
}

std::vector<ProgrammedBlock> lay_out(const tape::Program& program) {
  std::vector<ProgrammedBlock> out;
  out.reserve(program.blocks.size());
  GridPoint cur;
  for (size_t k = 0; k < program.blocks.size(); ++k) {
    const tape::Block& t = program.blocks[k];
    ProgrammedBlock b;
    b.index = k;
    b.tape = t;
    b.start = cur;
    b.end = {cur.x + t.dx, cur.y + t.dy};
    b.centre = {static_cast<double>(cur.x + t.i), static_cast<double>(cur.y + t.j)};
    out.push_back(b);
    cur = b.end;
  }
  return out;
}

double distance_to_block(const ProgrammedBlock& block, Vec2 q, double* along) {
  const Vec2 a = to_vec(block.start), b = to_vec(block.end);
  if (!block.is_arc()) return distance_to_segment(q, a, b, along);
  const Vec2 v = q - block.centre, ra = a - block.centre;
  const double sweep = block.sweep(), span = std::fabs(sweep);
  if (norm(v) > 0) {
    // Angle of q from the start, in the sweep's sense, in [0, 2 pi).
    double phi = std::atan2(ra.x * v.y - ra.y * v.x, ra.x * v.x + ra.y * v.y);
    if (sweep < 0) phi = -phi;
    if (phi < 0) phi += 2 * M_PI;
    if (phi <= span) {
      const double s = phi / span;
      const double r0 = norm(ra), r1 = norm(b - block.centre);
      if (along) *along = s;
      return std::fabs(norm(v) - (r0 + s * (r1 - r0)));
    }
  }
  const double da = norm(q - a), db = norm(q - b);
  if (along) *along = da <= db ? 0.0 : 1.0;
  return std::min(da, db);
}

}  // namespace ncinterp::checker
