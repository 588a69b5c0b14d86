// Joint classification for contours (see contour.h).
#include "geometry/contour.h"

#include <cmath>
#include <string>
#include <utility>

namespace ncinterp::firststage {

bool Contour::closed() const {
  if (segments.empty()) return false;
  const Vec2 d = segments.back().end() - segments.front().start();
  return norm(d) <= 1e-9 * (1.0 + norm(segments.front().start()));
}

Contour contour_from_segments(const std::string& file, Vec2 origin, std::vector<Segment> segments) {
  Contour c;
  c.file = file;
  c.origin = origin;
  for (size_t i = 0; i < segments.size(); ++i) {
    segments[i].source_index = static_cast<int>(i);
    c.element_names.push_back("segment " + std::to_string(i + 1));
  }
  c.segments = std::move(segments);
  return c;
}

double joint_turn(const Segment& a, const Segment& b) {
  const Vec2 ta = a.eval(1.0).d1, tb = b.eval(0.0).d1;
  if (norm(ta) == 0.0 || norm(tb) == 0.0) return M_PI;
  return std::fabs(std::atan2(cross(ta, tb), dot(ta, tb)));
}

bool smooth_joint(const Segment& a, const Segment& b) {
  if (a.rapid || b.rapid) return false;
  return joint_turn(a, b) <= kSmoothJointAngle;
}

}  // namespace ncinterp::firststage
