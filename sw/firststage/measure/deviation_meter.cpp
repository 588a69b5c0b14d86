// Dense-sampling deviation meter (see deviation_meter.h).
#include "measure/deviation_meter.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <unordered_map>

namespace ncinterp::firststage {
namespace {

using Polyline = std::vector<Vec2>;  // a run of points; consecutive points form segments

// Grid of cells holding the segments (polyline index, point index) that pass through.
class SegmentGrid {
 public:
  SegmentGrid(const std::vector<Polyline>& lines, double cell) : lines_(lines), cell_(cell) {
    for (size_t l = 0; l < lines.size(); ++l)
      for (size_t k = 0; k + 1 < lines[l].size(); ++k) {
        const Vec2 a = lines[l][k], b = lines[l][k + 1];
        const long x0 = cell_of(std::min(a.x, b.x)), x1 = cell_of(std::max(a.x, b.x));
        const long y0 = cell_of(std::min(a.y, b.y)), y1 = cell_of(std::max(a.y, b.y));
        for (long x = x0; x <= x1; ++x)
          for (long y = y0; y <= y1; ++y) cells_[key(x, y)].push_back({l, k});
      }
  }
  // Distance from p to the nearest segment.
  double distance(Vec2 p) const {
    const long cx = cell_of(p.x), cy = cell_of(p.y);
    double best = std::numeric_limits<double>::infinity();
    for (long ring = 0; ring < 64; ++ring) {
      if (best <= (ring - 1) * cell_) break;  // farther rings cannot be nearer
      for (long x = cx - ring; x <= cx + ring; ++x)
        for (long y = cy - ring; y <= cy + ring; ++y) {
          if (std::max(std::labs(x - cx), std::labs(y - cy)) != ring) continue;
          const auto it = cells_.find(key(x, y));
          if (it == cells_.end()) continue;
          for (const auto& s : it->second) best = std::min(best, segment_distance(p, s.first, s.second));
        }
    }
    return best;
  }

 private:
  long cell_of(double v) const { return static_cast<long>(std::floor(v / cell_)); }
  static long long key(long x, long y) { return (static_cast<long long>(x) << 32) ^ (y & 0xffffffffLL); }
  double segment_distance(Vec2 p, size_t l, size_t k) const {
    const Vec2 a = lines_[l][k], b = lines_[l][k + 1];
    const Vec2 ab = b - a;
    const double len2 = dot(ab, ab);
    const double t = len2 > 0 ? std::clamp(dot(p - a, ab) / len2, 0.0, 1.0) : 0.0;
    return norm(p - (a + t * ab));
  }
  const std::vector<Polyline>& lines_;
  double cell_;
  std::unordered_map<long long, std::vector<std::pair<size_t, size_t>>> cells_;
};

void sample_segment(const Segment& s, double step, Polyline& out) {
  // Length estimate from a coarse polyline, then an even parameter step.
  double len = 0.0;
  Vec2 prev = s.point(0.0);
  for (int i = 1; i <= 64; ++i) {
    const Vec2 p = s.point(i / 64.0);
    len += norm(p - prev);
    prev = p;
  }
  const long n = std::max(1L, static_cast<long>(std::ceil(len / step)));
  for (long i = out.empty() ? 0 : 1; i <= n; ++i) out.push_back(s.point(static_cast<double>(i) / n));
}

void sample_line(Vec2 a, Vec2 b, double step, Polyline& out) {
  const long n = std::max(1L, static_cast<long>(std::ceil(norm(b - a) / step)));
  for (long i = out.empty() ? 0 : 1; i <= n; ++i) out.push_back(a + (static_cast<double>(i) / n) * (b - a));
}

void sample_arc_move(Vec2 a, Vec2 b, Vec2 c, bool ccw, double step, Polyline& out) {
  const double ra = norm(a - c), rb = norm(b - c);
  const double ta = std::atan2(a.y - c.y, a.x - c.x);
  double sw = std::atan2(b.y - c.y, b.x - c.x) - ta;
  if (ccw && sw <= 0) sw += 2 * M_PI;
  if (!ccw && sw >= 0) sw -= 2 * M_PI;
  const long n = std::max(1L, static_cast<long>(std::ceil(std::fabs(sw) * std::max(ra, rb) / step)));
  for (long i = out.empty() ? 0 : 1; i <= n; ++i) {
    const double f = static_cast<double>(i) / n;
    const double r = ra + f * (rb - ra), th = ta + f * sw;
    out.push_back(c + r * Vec2{std::cos(th), std::sin(th)});
  }
}

double farthest(const std::vector<Polyline>& from, const SegmentGrid& to, long* count) {
  double worst = 0.0;
  for (const Polyline& l : from)
    for (const Vec2& p : l) {
      worst = std::max(worst, to.distance(p));
      ++*count;
    }
  return worst;
}

}  // namespace

DeviationReport measure_deviation(const Contour& contour, GridPoint start,
                                  const std::vector<Move>& moves, double blu_mm, double step_mm) {
  std::vector<Polyline> curve, path;
  for (const Segment& s : contour.segments) {
    if (s.rapid) {
      curve.emplace_back();
      continue;
    }
    if (curve.empty()) curve.emplace_back();
    sample_segment(s, step_mm, curve.back());
  }
  Vec2 cur = blu_mm * to_vec(start);
  for (const Move& m : moves) {
    const Vec2 to = blu_mm * to_vec(m.to);
    if (m.rapid) {
      path.emplace_back();
    } else {
      if (path.empty()) path.emplace_back();
      if (m.kind == MoveKind::kLine) sample_line(cur, to, step_mm, path.back());
      else sample_arc_move(cur, to, blu_mm * to_vec(m.centre), m.kind == MoveKind::kArcCcw, step_mm, path.back());
    }
    cur = to;
  }
  DeviationReport r;
  // About 8 samples per cell: a query looks at the 3 x 3 cells around it (more only when
  // the path is farther than a cell), so each costs a few dozen segment distances.
  const double cell = std::max(step_mm * 8, 1e-6);
  const SegmentGrid curve_grid(curve, cell), path_grid(path, cell);
  r.path_to_contour_mm = farthest(path, curve_grid, &r.samples);
  r.contour_to_path_mm = farthest(curve, path_grid, &r.samples);
  r.max_mm = std::max(r.path_to_contour_mm, r.contour_to_path_mm);
  return r;
}

}  // namespace ncinterp::firststage
