// Certified point-to-contour distance (see contour_distance.h).
#include "contour_distance.h"

#include <algorithm>
#include <boost/geometry.hpp>
#include <boost/geometry/index/rtree.hpp>
#include <cmath>
#include <limits>
#include <utility>

namespace ncinterp::checker {

namespace bg = boost::geometry;
namespace bgi = boost::geometry::index;
using BoxPoint = bg::model::point<double, 2, bg::cs::cartesian>;
using IndexBox = bg::model::box<BoxPoint>;
using IndexValue = std::pair<IndexBox, int>;

struct ContourDistance::Index {
  bgi::rtree<IndexValue, bgi::rstar<16>> tree;
};

namespace {

using firststage::SegmentKind;

Vec2 lerp(Vec2 a, Vec2 b, double t) { return a + t * (b - a); }
Vec2 mid(Vec2 a, Vec2 b) { return 0.5 * (a + b); }

// A sub-piece of a cubic in Bezier form over [u0, u1] of the segment's parameter.
struct Bezier {
  Vec2 b[4];
  double u0, u1;
};

Vec2 bezier_point(const Bezier& z, double t) {
  const Vec2 a = lerp(z.b[0], z.b[1], t), b = lerp(z.b[1], z.b[2], t), c = lerp(z.b[2], z.b[3], t);
  return lerp(lerp(a, b, t), lerp(b, c, t), t);
}

// Halves z at its parameter midpoint (de Casteljau).
void split(const Bezier& z, Bezier& left, Bezier& right) {
  const Vec2 l1 = mid(z.b[0], z.b[1]), m = mid(z.b[1], z.b[2]), r2 = mid(z.b[2], z.b[3]);
  const Vec2 l2 = mid(l1, m), r1 = mid(m, r2), c = mid(l2, r1);
  const double um = 0.5 * (z.u0 + z.u1);
  left = {{z.b[0], l1, l2, c}, z.u0, um};
  right = {{c, r1, r2, z.b[3]}, um, z.u1};
}

double wrap_angle(double a) {  // to (-pi, pi]
  while (a > M_PI) a -= 2 * M_PI;
  while (a <= -M_PI) a += 2 * M_PI;
  return a;
}

}  // namespace

double ContourDistance::Box::distance_sq(Vec2 q) const {
  const double dx = std::max({x0 - q.x, 0.0, q.x - x1});
  const double dy = std::max({y0 - q.y, 0.0, q.y - y1});
  return dx * dx + dy * dy;
}

ContourDistance::ContourDistance(std::vector<Segment> segments) : segments_(std::move(segments)) {
  build_pieces();
  std::vector<IndexValue> boxes;
  boxes.reserve(pieces_.size());
  for (size_t s = 0; s < pieces_.size(); ++s) {
    const Box& b = pieces_[s].box;
    boxes.push_back({IndexBox(BoxPoint(b.x0, b.y0), BoxPoint(b.x1, b.y1)), static_cast<int>(s)});
  }
  index_ = std::make_shared<const Index>(Index{{boxes.begin(), boxes.end()}});  // packed (bulk loaded)
}

void ContourDistance::build_pieces() {
  pieces_.resize(segments_.size());
  for (size_t s = 0; s < segments_.size(); ++s) {
    const Segment& seg = segments_[s];
    Piece& piece = pieces_[s];
    if (seg.is_arc()) {
      // The whole circle's box: a valid (if loose) bound for any part of it.
      const Vec2 c = seg.centre();
      const double r = seg.radius();
      piece.box = {c.x - r, c.y - r, c.x + r, c.y + r};
      continue;
    }
    // Power basis from the derivatives at the ends, then Bezier control points.
    const firststage::CurvePoint e0 = seg.eval(0.0), e1 = seg.eval(1.0);
    const Vec2 c0 = e0.p, c1 = e0.d1, c2 = 0.5 * e0.d2, c3 = (1.0 / 6.0) * (e1.d2 - e0.d2);
    piece.bezier[0] = c0;
    piece.bezier[1] = c0 + (1.0 / 3.0) * c1;
    piece.bezier[2] = c0 + (1.0 / 3.0) * (2.0 * c1 + c2);
    piece.bezier[3] = c0 + c1 + c2 + c3;
    Box& b = piece.box;
    b = {piece.bezier[0].x, piece.bezier[0].y, piece.bezier[0].x, piece.bezier[0].y};
    for (int k = 1; k < 4; ++k) {
      b.x0 = std::min(b.x0, piece.bezier[k].x);
      b.y0 = std::min(b.y0, piece.bezier[k].y);
      b.x1 = std::max(b.x1, piece.bezier[k].x);
      b.y1 = std::max(b.y1, piece.bezier[k].y);
    }
  }
}

// Reach m of a candidate list, BLU (the checker's units): a list serves the pulses within
// m of where it was made. Larger lists serve longer and cost more per query.
constexpr double kCandidateReach = 16.0;

void ContourDistance::refresh_candidates(Vec2 q) const {
  const auto& tree = index_->tree;
  // U: the distance to the last answer's segment, or to the segment of the nearest box.
  ContourFoot u;
  u.distance = std::numeric_limits<double>::infinity();
  if (have_candidates_) {
    search(hint_, q, u);
  } else {
    for (auto it = tree.qbegin(bgi::nearest(BoxPoint(q.x, q.y), 1)); it != tree.qend(); ++it)
      search(it->second, q, u);
  }
  const double reach = u.distance + 2 * kCandidateReach;
  const IndexBox around(BoxPoint(q.x - reach, q.y - reach), BoxPoint(q.x + reach, q.y + reach));
  candidates_.clear();
  for (auto it = tree.qbegin(bgi::intersects(around)); it != tree.qend(); ++it)
    if (pieces_[it->second].box.distance_sq(q) <= reach * reach) candidates_.push_back(it->second);
  std::sort(candidates_.begin(), candidates_.end());
  centre_ = q;
  have_candidates_ = true;
}

ContourFoot ContourDistance::nearest(Vec2 q) const {
  ContourFoot best;
  best.distance = std::numeric_limits<double>::infinity();
  if (pieces_.empty()) return best;
  if (!have_candidates_ || norm(q - centre_) > kCandidateReach) refresh_candidates(q);
  search(hint_, q, best);
  for (int s : candidates_) {
    if (s == hint_) continue;
    if (pieces_[s].box.distance_sq(q) >= best.distance * best.distance) continue;
    search(s, q, best);
  }
  hint_ = best.segment;
  return best;
}

ContourFoot ContourDistance::nearest_on(int segment, Vec2 q) const {
  ContourFoot best;
  best.distance = std::numeric_limits<double>::infinity();
  search(segment, q, best);
  return best;
}

void ContourDistance::search(int s, Vec2 q, ContourFoot& best) const {
  const Segment& seg = segments_[s];
  if (seg.is_arc()) {
    search_arc(s, q, best);
  } else if (seg.kind() == SegmentKind::kLine) {
    const Piece& p = pieces_[s];
    double t = 0.0;
    const double d = distance_to_segment(q, p.bezier[0], p.bezier[3], &t);
    if (d < best.distance) best = {d, s, t, lerp(p.bezier[0], p.bezier[3], t)};
  } else {
    search_cubic(s, q, best);
  }
}

void ContourDistance::search_arc(int s, Vec2 q, ContourFoot& best) const {
  const Segment& seg = segments_[s];
  const Vec2 c = seg.centre();
  const double r = seg.radius(), sweep = seg.sweep();
  const Vec2 v = q - c;
  const double rq = norm(v);
  double u = 0.0;
  bool inside = false;
  if (rq > 0) {
    // Angle of q from the arc's start, measured in the sweep's sense.
    double a = wrap_angle(std::atan2(v.y, v.x) - seg.start_angle());
    if (sweep < 0) a = -a;
    if (a < 0) a += 2 * M_PI;
    const double span = std::fabs(sweep);
    if (a <= span) {
      inside = true;
      u = span > 0 ? a / span : 0.0;
    }
  }
  if (inside) {
    const double d = std::fabs(rq - r);
    if (d < best.distance) best = {d, s, u, seg.point(u)};
    return;
  }
  for (double ue : {0.0, 1.0}) {
    const Vec2 p = seg.point(ue);
    const double d = norm(q - p);
    if (d < best.distance) best = {d, s, ue, p};
  }
}

void ContourDistance::search_cubic(int s, Vec2 q, ContourFoot& best) const {
  const Piece& piece = pieces_[s];
  // Depth-first; a stack of at most ~2 pieces per level is live at a time.
  Bezier stack[128];
  int top = 0;
  stack[top++] = {{piece.bezier[0], piece.bezier[1], piece.bezier[2], piece.bezier[3]}, 0.0, 1.0};
  while (top > 0) {
    const Bezier z = stack[--top];
    double t = 0.0;
    const double dc = distance_to_segment(q, z.b[0], z.b[3], &t);
    // Hull width: the farthest inner control point from the chord (the whole hull, hence
    // the whole piece, lies within this distance of the chord).
    const double w = std::max(distance_to_segment(z.b[1], z.b[0], z.b[3]),
                              distance_to_segment(z.b[2], z.b[0], z.b[3]));
    const double lower = dc - w;
    if (lower >= best.distance - kDistanceAccuracy) continue;  // cannot improve enough
    const Vec2 p = bezier_point(z, t);
    const double d = norm(q - p);
    if (d < best.distance) best = {d, s, z.u0 + t * (z.u1 - z.u0), p};
    if (best.distance - lower <= kDistanceAccuracy) continue;  // bracket narrow enough
    if (z.u1 - z.u0 < 1e-14 || top + 2 > 128) continue;       // numerical floor
    Bezier l, r;
    split(z, l, r);
    // Visit the half nearer q first (pushed last): it tightens the bound sooner.
    const bool left_first = t < 0.5;
    stack[top++] = left_first ? r : l;
    stack[top++] = left_first ? l : r;
  }
}

}  // namespace ncinterp::checker
