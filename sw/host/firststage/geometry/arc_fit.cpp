// Arcs from inputs (see arc_fit.h).
#include "geometry/arc_fit.h"

#include <cmath>

namespace ncinterp::firststage {

double arc_radius_mismatch(Vec2 start, Vec2 end, Vec2 centre) {
  return std::fabs(norm(end - centre) - norm(start - centre));
}

Segment arc_through(Vec2 start, Vec2 end, Vec2 centre, bool ccw) {
  const Vec2 chord = end - start;
  const double len = norm(chord);
  if (len > 1e-12 * (1.0 + norm(start))) {
    const Vec2 mid = 0.5 * (start + end);
    const Vec2 along = (1.0 / len) * chord;
    centre = centre - dot(centre - mid, along) * along;  // onto the bisector
  }
  const double r = norm(start - centre);
  const double a0 = std::atan2(start.y - centre.y, start.x - centre.x);
  double sweep = 2.0 * M_PI;
  if (len > 1e-12 * (1.0 + norm(start))) {
    const double a1 = std::atan2(end.y - centre.y, end.x - centre.x);
    sweep = std::remainder(a1 - a0, 2.0 * M_PI);  // (-pi, pi]
    if (ccw && sweep <= 0) sweep += 2.0 * M_PI;
    if (!ccw && sweep >= 0) sweep -= 2.0 * M_PI;
  }
  return Segment::arc(centre, r, a0, ccw ? std::fabs(sweep) : -std::fabs(sweep));
}

bool arc_centre_from_radius(Vec2 start, Vec2 end, double r, bool ccw, Vec2* centre) {
  const Vec2 chord = end - start;
  const double len = norm(chord);
  if (len == 0.0 || len > 2.0 * std::fabs(r) * (1.0 + 1e-9)) return false;
  const double h = std::sqrt(std::max(r * r - 0.25 * len * len, 0.0));
  const Vec2 left = perp((1.0 / len) * chord);
  // Counter-clockwise short arcs have their centre on the left of start -> end.
  const double side = (ccw ? 1.0 : -1.0) * (r > 0 ? 1.0 : -1.0);
  *centre = 0.5 * (start + end) + side * h * left;
  return true;
}

}  // namespace ncinterp::firststage
