// Test-side deviation checker (see independent_checker.h).
#include "independent_checker.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace ncinterp::test {
namespace {

double seg_dist(P2 p, P2 a, P2 b) {
  const double vx = b.x - a.x, vy = b.y - a.y;
  const double l2 = vx * vx + vy * vy;
  double t = l2 > 0 ? ((p.x - a.x) * vx + (p.y - a.y) * vy) / l2 : 0.0;
  t = std::min(1.0, std::max(0.0, t));
  return std::hypot(p.x - (a.x + t * vx), p.y - (a.y + t * vy));
}

}  // namespace

CheckResult check_path(const std::vector<P2>& curve, const std::vector<P2>& path, double step) {
  CheckResult r;
  const long nc = static_cast<long>(curve.size()), np = static_cast<long>(path.size());
  // Normal measure: curve samples in order, path segments near a moving pointer.
  long k = 0;
  for (long i = 1; i + 1 < nc; ++i) {
    const double tx = curve[i + 1].x - curve[i - 1].x, ty = curve[i + 1].y - curve[i - 1].y;
    const double tl = std::hypot(tx, ty);
    const double nx = -ty / tl, ny = tx / tl;
    double best = std::numeric_limits<double>::infinity();
    long best_k = k;
    for (long j = std::max(0L, k - 3); j < std::min(np - 1, k + 200); ++j) {
      const double ex = path[j + 1].x - path[j].x, ey = path[j + 1].y - path[j].y;
      const double den = nx * ey - ny * ex;  // cross(n, e)
      if (std::fabs(den) < 1e-15) continue;
      const double ax = path[j].x - curve[i].x, ay = path[j].y - curve[i].y;
      const double s = (ax * ey - ay * ex) / den;   // along the normal
      const double t = (ax * ny - ay * nx) / den;   // along the path segment
      if (t < -1e-12 || t > 1 + 1e-12) continue;
      if (std::fabs(s) < best) best = std::fabs(s), best_k = j;
    }
    if (!std::isfinite(best)) {
      ++r.unmatched;
      continue;
    }
    k = best_k;
    r.normal_max = std::max(r.normal_max, best);
  }
  // Path measure: points along each path segment, curve segments near a moving pointer.
  double curve_len = 0.0;
  for (long i = 0; i + 1 < nc; ++i) curve_len += std::hypot(curve[i + 1].x - curve[i].x, curve[i + 1].y - curve[i].y);
  const double spacing = curve_len / std::max(1L, nc - 1);
  long c = 0;
  for (long j = 0; j + 1 < np; ++j) {
    const double len = std::hypot(path[j + 1].x - path[j].x, path[j + 1].y - path[j].y);
    const long parts = std::max(1L, static_cast<long>(std::ceil(len / step)));
    for (long q = 0; q <= parts; ++q) {
      const double f = static_cast<double>(q) / parts;
      const P2 p{path[j].x + f * (path[j + 1].x - path[j].x), path[j].y + f * (path[j + 1].y - path[j].y)};
      double best = std::numeric_limits<double>::infinity();
      long best_c = c;
      const long window = static_cast<long>(2.0 * len / spacing) + 50;
      for (long i = std::max(0L, c - window); i < std::min(nc - 1, c + window); ++i) {
        const double d = seg_dist(p, curve[i], curve[i + 1]);
        if (d < best) best = d, best_c = i;
      }
      c = best_c;
      r.path_max = std::max(r.path_max, best);
    }
  }
  return r;
}

}  // namespace ncinterp::test
