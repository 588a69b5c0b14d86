// Reference chord counts (see chord_bounds.h).
#include "measure/chord_bounds.h"

#include <cmath>

namespace ncinterp::firststage {

double two_sided_lower_bound(const Contour& contour, double delta_mm) {
  double total = 0.0;
  for (const Segment& s : contour.segments) {
    if (s.rapid || s.kind() == SegmentKind::kLine) continue;
    // Composite Simpson over u of sqrt(|kappa| / (16 delta)) |p'(u)|.
    const int n = 2000;
    auto f = [&](double u) {
      const CurvePoint c = s.eval(u);
      const double sp = norm(c.d1);
      if (sp == 0.0) return 0.0;
      const double kappa = std::fabs(cross(c.d1, c.d2)) / (sp * sp * sp);
      return std::sqrt(kappa / (16.0 * delta_mm)) * sp;
    };
    double sum = f(0.0) + f(1.0);
    for (int i = 1; i < n; ++i) sum += (i % 2 ? 4.0 : 2.0) * f(static_cast<double>(i) / n);
    total += sum / (3.0 * n);
  }
  return total;
}

long grbl_arc_segments(const Contour& contour, double delta_mm, int* arcs_counted) {
  long total = 0;
  int arcs = 0;
  for (const Segment& s : contour.segments) {
    if (!s.is_arc()) continue;
    const double r = s.radius();
    const long seg = static_cast<long>(
        std::floor(std::fabs(0.5 * s.sweep() * r) / std::sqrt(delta_mm * (2.0 * r - delta_mm))));
    total += std::max(seg, 1L);
    ++arcs;
  }
  if (arcs_counted) *arcs_counted = arcs;
  return total;
}

}  // namespace ncinterp::firststage
