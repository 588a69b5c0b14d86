// Test support for circle mode (see the header).
#include "arc_cases.h"

#include <cmath>

namespace ncinterp::circle_study {

double QuadrantArc::start_radius() const {
  return std::hypot(static_cast<double>(x0), static_cast<double>(y0));
}

double QuadrantArc::end_radius() const {
  return std::hypot(static_cast<double>(x1), static_cast<double>(y1));
}

std::string QuadrantArc::describe() const {
  return std::string(ccw ? "G03" : "G02") + " from (" + std::to_string(x0) + ", " +
         std::to_string(y0) + ") to (" + std::to_string(x1) + ", " + std::to_string(y1) +
         ") about the centre";
}

QuadrantArc full_quadrant(int64_t r, int q, bool ccw) {
  const int64_t axis[4][2] = {{r, 0}, {0, r}, {-r, 0}, {0, -r}};
  const int64_t* a = axis[q & 3];
  const int64_t* b = axis[(q + 1) & 3];
  QuadrantArc arc;
  arc.ccw = ccw;
  if (!ccw) std::swap(a, b);
  arc.x0 = a[0];
  arc.y0 = a[1];
  arc.x1 = b[0];
  arc.y1 = b[1];
  return arc;
}

QuadrantArc random_arc(std::mt19937_64& rng, int64_t max_radius) {
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  for (;;) {
    const double r = std::exp(unit(rng) * std::log(static_cast<double>(max_radius)));
    const int q = static_cast<int>(rng() % 4);
    const bool ccw = rng() % 2 == 0;
    if (rng() % 4 == 0) {
      const QuadrantArc arc = full_quadrant(std::llround(std::floor(r)), q, ccw);
      if (check_arc(arc.words(), 30) == TapeError::kNone) return arc;
      continue;
    }
    double a0 = unit(rng) * M_PI / 2, a1 = unit(rng) * M_PI / 2;
    if (a0 > a1) std::swap(a0, a1);
    if (!ccw) std::swap(a0, a1);  // travel from a0 to a1
    a0 += q * M_PI / 2;
    a1 += q * M_PI / 2;
    QuadrantArc arc;
    arc.ccw = ccw;
    arc.x0 = std::llround(r * std::cos(a0));
    arc.y0 = std::llround(r * std::sin(a0));
    arc.x1 = std::llround(r * std::cos(a1));
    arc.y1 = std::llround(r * std::sin(a1));
    if (std::llabs(arc.x0) > max_radius || std::llabs(arc.y0) > max_radius ||
        std::llabs(arc.x1) > max_radius || std::llabs(arc.y1) > max_radius)
      continue;
    if (check_arc(arc.words(), 30) == TapeError::kNone) return arc;
  }
}

ArcRunStats run_arc(const QuadrantArc& arc, unsigned inc_width, uint64_t max_iterations) {
  const ArcWords w = arc.words();
  const ArcGeometry g = arc_geometry(w, inc_width);
  CircleDda dda;
  dda.load(g, !w.dx_neg, !w.dy_neg);
  ArcRunStats s;
  s.k = g.k;
  s.x = arc.x0;
  s.y = arc.y0;
  const double r0 = arc.start_radius(), r1 = arc.end_radius();
  // Angle travelled from the start, in the arc's direction, as a fraction of the sweep.
  const double a0 = std::atan2(double(arc.y0), double(arc.x0));
  const double sweep = std::fabs(std::remainder(std::atan2(double(arc.y1), double(arc.x1)) - a0,
                                                2 * M_PI));
  while (!dda.done() && s.iterations < max_iterations) {
    const CircleDda::Steps st = dda.iterate();
    ++s.iterations;
    const bool step[2] = {st.x, st.y};
    for (int a = 0; a < 2; ++a) {
      if (!step[a]) continue;
      const bool plus = dda.dir(a);
      ++s.pulses[a][plus ? 1 : 0];
      (a == 0 ? s.x : s.y) += plus ? 1 : -1;
    }
    if (st.x || st.y) {
      const double e = std::fabs(std::hypot(static_cast<double>(s.x), static_cast<double>(s.y)) - r0);
      if (e > s.max_radial_error) {
        s.max_radial_error = e;
        s.worst_x = s.x;
        s.worst_y = s.y;
      }
      const double phi = std::fabs(
          std::remainder(std::atan2(double(s.y), double(s.x)) - a0, 2 * M_PI));
      const double t = sweep > 0 ? std::min(1.0, phi / sweep) : 1.0;
      const double es = std::fabs(std::hypot(double(s.x), double(s.y)) - (r0 + (r1 - r0) * t));
      if (es > s.max_spiral_error) s.max_spiral_error = es;
    }
  }
  s.finished = dda.done();
  return s;
}

}  // namespace ncinterp::circle_study
