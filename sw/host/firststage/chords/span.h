// A span: consecutive segments that chords may cross (one smooth run, or one zone), seen
// as one curve C(t) with t in [0, n]: segment i covers t in [i, i + 1].
// Idea: the chord methods and the deviation measure work on t and never care where one
// segment ends; joints are visited explicitly where the derivative may jump.
#pragma once
#include <algorithm>
#include <cmath>

#include "geometry/segment.h"

namespace ncinterp::firststage {

class Span {
 public:
  Span(const Segment* segments, int count) : seg_(segments), n_(count) {}
  int size() const { return n_; }
  double t_end() const { return n_; }
  int index(double t) const { return std::clamp(static_cast<int>(std::floor(t)), 0, n_ - 1); }
  const Segment& segment(int i) const { return seg_[i]; }
  CurvePoint eval(double t) const {
    const int i = index(t);
    return seg_[i].eval(t - i);
  }
  // At a joint (integer t), the end of the segment before it.
  CurvePoint eval_before(double t) const {
    const int i = std::clamp(static_cast<int>(std::ceil(t)) - 1, 0, n_ - 1);
    return seg_[i].eval(t - i);
  }
  // The first joint (or the span's end) after t: searches step no farther at a time, so
  // they see every segment's bend.
  double next_joint(double t) const { return std::min(std::floor(t) + 1.0, t_end()); }
  Vec2 point(double t) const {
    const int i = index(t);
    return seg_[i].point(t - i);
  }

 private:
  const Segment* seg_;
  int n_;
};

// Signed curvature times speed, d(theta)/dt, of a curve point.
inline double turn_rate(const CurvePoint& c) {
  const double s2 = dot(c.d1, c.d1);
  return s2 > 0 ? cross(c.d1, c.d2) / s2 : 0.0;
}

}  // namespace ncinterp::firststage
