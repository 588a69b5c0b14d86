// Total-error reference (see reference_contour.h).
#include "reference_contour.h"

#include <cmath>

namespace ncinterp::checker {
namespace {

std::vector<Segment> cutting_in_blu(const firststage::Contour& c, double to_blu) {
  std::vector<Segment> out;
  for (const Segment& s : c.segments)
    if (!s.rapid) out.push_back(s.scaled(to_blu));
  return out;
}

}  // namespace

ReferenceContour::ReferenceContour(const firststage::Contour& contour, const ReferenceOptions& options)
    : options_(options),
      radius_(options.cutter_radius_mm / options.blu_mm),
      cut_(cutting_in_blu(contour, 1.0 / options.blu_mm)) {
  const double to_blu = 1.0 / options.blu_mm;
  const int n = static_cast<int>(contour.segments.size());
  // Convex corners between consecutive cutting segments (closed contours wrap around).
  const bool closed = contour.closed();
  for (int s = 0; s < n; ++s) {
    const Segment& seg = contour.segments[s];
    if (seg.rapid) {
      rapids_.push_back(seg.scaled(to_blu));
      continue;
    }
    const int idx = seg.source_index;
    names_.push_back(idx >= 0 && idx < static_cast<int>(contour.element_names.size())
                         ? contour.element_names[idx]
                         : "segment " + std::to_string(s + 1));
    auto convex = [&](int a, int b) -> char {
      if (a < 0 || b < 0 || a >= n || b >= n) return 0;
      const Segment& sa = contour.segments[a];
      const Segment& sb = contour.segments[b];
      if (sa.rapid || sb.rapid || firststage::joint_turn(sa, sb) <= firststage::kSmoothJointAngle)
        return 0;
      const double turn = cross(sa.eval(1.0).d1, sb.eval(0.0).d1);
      // Convex: the path turns away from the cutter's side.
      return options.cutter_left ? turn < 0 : turn > 0;
    };
    const int prev = s > 0 ? s - 1 : (closed ? n - 1 : -1);
    const int next = s + 1 < n ? s + 1 : (closed ? 0 : -1);
    corner_start_.push_back(convex(prev, s));
    corner_end_.push_back(convex(s, next));
  }
}

bool ReferenceContour::convex_corner_at(int segment, double u) const {
  if (segment < 0) return false;
  return (u <= 0.0 && corner_start_[segment]) || (u >= 1.0 && corner_end_[segment]);
}

TotalError ReferenceContour::measure(Vec2 position) const {
  TotalError e;
  const Vec2 start = to_vec(options_.start);
  const ContourFoot f = cut_.nearest(start + position);
  e.segment = f.segment;
  e.foot = f.foot - start;
  if (radius_ <= 0.0) {
    e.error = e.signed_excess = f.distance;
    return e;
  }
  e.signed_excess = f.distance - radius_;
  e.error = std::fabs(e.signed_excess);
  e.corner = e.signed_excess > 0 && convex_corner_at(f.segment, f.u);
  return e;
}

bool ReferenceContour::is_rapid(const ProgrammedBlock& block, double tol_blu) const {
  if (rapids_.empty()) return false;
  const Vec2 start = to_vec(options_.start);
  const double samples[] = {0.0, 0.5, 1.0};
  bool on_cut = true;
  for (double s : samples) {
    const Vec2 q = block.point_at(s);
    const TotalError e = measure(q);
    if (e.error > tol_blu && !e.corner) on_cut = false;
  }
  if (on_cut) return false;
  // The offset re-aims a rapid at the next chain's start, up to sqrt(2) R from the input's
  // rapid end (a corner of the offset path); + 1 BLU for the grid rounding of the ends.
  const double reach = tol_blu + 1.5 * radius_ + 1.0;
  for (const Segment& r : rapids_) {
    bool along = true;
    for (double s : samples) {
      const Vec2 q = start + block.point_at(s);
      if (distance_to_segment(q, r.start(), r.end()) > reach) along = false;
    }
    if (along) return true;
  }
  return false;
}

std::string ReferenceContour::element_name(int segment) const {
  if (segment < 0 || segment >= static_cast<int>(names_.size())) return "";
  return names_[segment];
}

}  // namespace ncinterp::checker
