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
  for (size_t s = 0; s < contour.segments.size(); ++s) {
    const Segment& seg = contour.segments[s];
    if (seg.rapid) {
      rapids_.push_back(seg.scaled(to_blu));
      continue;
    }
    const int idx = seg.source_index;
    names_.push_back(idx >= 0 && idx < static_cast<int>(contour.element_names.size())
                         ? contour.element_names[idx]
                         : "segment " + std::to_string(s + 1));
  }
}

void ReferenceContour::set_tool_path(const std::vector<ProgrammedBlock>& blocks,
                                     const std::vector<bool>& rapid, const std::vector<double>& bounds) {
  const Vec2 start = to_vec(options_.start);
  std::vector<Segment> segs;
  path_bound_.clear();
  for (size_t k = 0; k < blocks.size(); ++k) {
    const ProgrammedBlock& b = blocks[k];
    if (rapid[k] || (b.start == b.end && !b.is_arc())) continue;
    if (b.is_arc()) {
      const Vec2 ra = to_vec(b.start) - b.centre;
      segs.push_back(Segment::arc(start + b.centre, norm(ra), std::atan2(ra.y, ra.x), b.sweep()));
      // The arc segment has the start radius; the end radius differs by < 1 BLU.
      path_bound_.push_back(bounds[k] + std::fabs(norm(to_vec(b.end) - b.centre) - norm(ra)));
    } else {
      segs.push_back(Segment::line(start + to_vec(b.start), start + to_vec(b.end)));
      path_bound_.push_back(bounds[k]);
    }
  }
  path_ = ContourDistance(std::move(segs));
}

TotalError ReferenceContour::centre_only(Vec2 position) const {
  TotalError e;
  const Vec2 start = to_vec(options_.start);
  const ContourFoot f = cut_.nearest(start + position);
  e.segment = f.segment;
  e.foot = f.foot - start;
  e.signed_excess = f.distance - radius_;
  e.error = radius_ > 0 ? std::fabs(e.signed_excess) : f.distance;
  return e;
}

TotalError ReferenceContour::measure(Vec2 position) const {
  TotalError e = centre_only(position);
  if (radius_ <= 0.0 || e.signed_excess <= 0.0 || path_.empty()) return e;
  // Outside the equidistant: how far is the foot from the cutter's whole path?
  const ContourFoot reach = path_.nearest(to_vec(options_.start) + e.foot);
  const double uncut = std::max(0.0, reach.distance + path_bound_[reach.segment] - radius_);
  if (uncut < e.error) {
    e.error = uncut;
    e.outside = true;
  }
  return e;
}

std::string ReferenceContour::element_name(int segment) const {
  if (segment < 0 || segment >= static_cast<int>(names_.size())) return "";
  return names_[segment];
}

}  // namespace ncinterp::checker
