// Test-side deviation checker (see independent_checker.h).
// The exact ("wide") search scans the whole other polyline but skips by the triangle
// inequality: from a vertex at distance D from the query point, every point within an
// arc length D - best along the polyline is farther than best, so the scan jumps there
// (binary search in the cumulative lengths). Far parts of the polyline cost a few jumps;
// the result is the brute-force minimum over every segment.
#include "independent_checker.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace ncinterp::test {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

double dist(P2 a, P2 b) { return std::hypot(a.x - b.x, a.y - b.y); }

double seg_dist(P2 p, P2 a, P2 b) {
  const double vx = b.x - a.x, vy = b.y - a.y;
  const double l2 = vx * vx + vy * vy;
  double t = l2 > 0 ? ((p.x - a.x) * vx + (p.y - a.y) * vy) / l2 : 0.0;
  t = std::min(1.0, std::max(0.0, t));
  return std::hypot(p.x - (a.x + t * vx), p.y - (a.y + t * vy));
}

// A polyline with its cumulative lengths, for the skipping scan.
class Polyline {
 public:
  explicit Polyline(const std::vector<P2>& pts) : p_(pts), s_(pts.size(), 0.0) {
    for (size_t i = 1; i < pts.size(); ++i) s_[i] = s_[i - 1] + dist(pts[i - 1], pts[i]);
  }
  long segments() const { return static_cast<long>(p_.size()) - 1; }
  const P2& operator[](long i) const { return p_[static_cast<size_t>(i)]; }
  double length() const { return s_.back(); }
  // Minimum over every segment m of measure(m), where measure(m) >= the distance from q
  // to segment m (so segments farther than the best so far can be skipped). `best` and
  // `at` hold an upper bound and its segment on entry (kInf / -1 for none).
  template <class Measure>
  void scan(P2 q, Measure measure, double* best, long* at) const {
    for (long m = 0; m < segments();) {
      const double v = measure(m);
      if (v < *best) *best = v, *at = m;
      const double reach = s_[static_cast<size_t>(m)] + dist(q, p_[static_cast<size_t>(m)]) - *best;
      // First segment whose far end lies beyond `reach`: everything before is too far.
      const long next = static_cast<long>(std::upper_bound(s_.begin(), s_.end(), reach) - s_.begin()) - 1;
      m = std::max(m + 1, next);
    }
  }

 private:
  const std::vector<P2>& p_;
  std::vector<double> s_;
};

// Distance along the normal (nx, ny) at c to path segment j; infinity when the normal's
// line misses the segment.
double normal_hit(P2 c, double nx, double ny, const Polyline& path, long j) {
  const P2 a = path[j], b = path[j + 1];
  const double ex = b.x - a.x, ey = b.y - a.y;
  const double den = nx * ey - ny * ex;  // cross(n, e)
  if (std::fabs(den) < 1e-15) return kInf;
  const double ax = a.x - c.x, ay = a.y - c.y;
  const double s = (ax * ey - ay * ex) / den;  // along the normal
  const double t = (ax * ny - ay * nx) / den;  // along the path segment
  if (t < -1e-12 || t > 1 + 1e-12) return kInf;
  return std::fabs(s);
}

// Local minimum of the distance from p to the polyline's segments, by descent from the
// segment *at with a few segments of patience each way; *at receives its segment. An
// upper bound of the true distance (the exact one whenever the descent found the nearest).
double descend(P2 p, const Polyline& line, long* at) {
  double best = seg_dist(p, line[*at], line[*at + 1]);
  const long start = *at;
  for (const long dir : {1L, -1L}) {
    for (long m = start + dir, misses = 0; m >= 0 && m < line.segments() && misses < 4; m += dir) {
      const double v = seg_dist(p, line[m], line[m + 1]);
      if (v < best) best = v, *at = m, misses = 0;
      else ++misses;
    }
  }
  return best;
}

double exact_distance(P2 p, const Polyline& line, long* at, double best) {
  line.scan(p, [&](long m) { return seg_dist(p, line[m], line[m + 1]); }, &best, at);
  return best;
}

}  // namespace

CheckResult check_path(const std::vector<P2>& curve_pts, const std::vector<P2>& path_pts,
                       double step, const std::vector<P2>& corners, double exact_above) {
  CheckResult r;
  if (curve_pts.size() < 2 || path_pts.size() < 2) {
    r.unmatched = static_cast<long>(curve_pts.size());
    return r;
  }
  const Polyline curve(curve_pts), path(path_pts);
  const long nc = curve.segments() + 1, np = path.segments();
  const double spacing = curve.length() / static_cast<double>(nc - 1);

  // Corner zones: centre and radius (the nearest path vertex, plus one sample spacing).
  std::vector<std::pair<P2, double>> zones;
  std::vector<P2> zone_centres = corners;
  zone_centres.push_back(curve[0]);
  zone_centres.push_back(curve[nc - 1]);
  for (const P2& z : zone_centres) {
    double nearest = kInf;
    for (long j = 0; j <= np; ++j) nearest = std::min(nearest, dist(z, path[j]));
    zones.push_back({z, nearest + spacing});
  }
  const auto in_zone = [&](P2 c) {
    for (const auto& z : zones)
      if (dist(c, z.first) <= z.second) return true;
    return false;
  };

  // Normal measure: curve samples in order, path segments near a pointer.
  long k = 0;
  for (long i = 0; i < nc; ++i) {
    const P2 c = curve[i];
    ++r.samples;
    double best = kInf;
    long at = -1;
    if (in_zone(c)) {
      ++r.corner_samples;
      best = exact_distance(c, path, &at, kInf);
    } else {
      const P2 prev = curve[std::max(0L, i - 1)], next = curve[std::min(nc - 1, i + 1)];
      const double tx = next.x - prev.x, ty = next.y - prev.y;
      const double tl = std::hypot(tx, ty);
      if (tl == 0.0) continue;
      const double nx = -ty / tl, ny = tx / tl;
      for (long j = std::max(0L, k - 2); j < std::min(np, k + 4); ++j) {
        const double v = normal_hit(c, nx, ny, path, j);
        if (v < best) best = v, at = j;
      }
      if (best > std::max(r.normal_max, exact_above)) {  // a new maximum, or a miss: measure exactly
        ++r.wide_searches;
        path.scan(c, [&](long j) { return normal_hit(c, nx, ny, path, j); }, &best, &at);
      }
      if (!std::isfinite(best)) {
        ++r.unmatched;
        continue;
      }
      k = at;
    }
    if (best > r.normal_max) r.normal_max = best, r.normal_worst = c;
  }

  // Path measure: points every `step` along the path, curve segments near a pointer.
  long ci = 0;
  for (long j = 0; j < np; ++j) {
    const P2 a = path[j], b = path[j + 1];
    const long parts = std::max(1L, static_cast<long>(std::ceil(dist(a, b) / step)));
    for (long q = j == 0 ? 0 : 1; q <= parts; ++q) {
      const double f = static_cast<double>(q) / parts;
      const P2 p{a.x + f * (b.x - a.x), a.y + f * (b.y - a.y)};
      ++r.samples;
      double best = descend(p, curve, &ci);
      if (best > std::max(r.path_max, exact_above)) {
        ++r.wide_searches;
        best = exact_distance(p, curve, &ci, best);
      }
      if (best > r.path_max) r.path_max = best, r.path_worst = p;
    }
  }
  return r;
}

DistanceRange distance_range(const std::vector<P2>& points,
                             const std::vector<std::vector<P2>>& lines) {
  DistanceRange r;
  std::vector<Polyline> polylines;
  for (const auto& l : lines)
    if (l.size() >= 2) polylines.emplace_back(l);
  std::vector<long> hint(polylines.size(), 0);
  for (const P2& p : points) {
    double d = kInf;
    for (size_t k = 0; k < polylines.size(); ++k)
      d = std::min(d, exact_distance(p, polylines[k], &hint[k], descend(p, polylines[k], &hint[k])));
    if (d < r.min) r.min = d, r.at_min = p;
    if (d > r.max) r.max = d, r.at_max = p;
  }
  return r;
}

}  // namespace ncinterp::test
