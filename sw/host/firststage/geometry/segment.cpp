// Segment evaluation and the tangent-parallel parameters (see segment.h).
#include "geometry/segment.h"

#include <algorithm>
#include <cmath>

namespace ncinterp::firststage {

const char* segment_kind_name(SegmentKind kind) {
  switch (kind) {
    case SegmentKind::kLine: return "line";
    case SegmentKind::kArc: return "arc";
    case SegmentKind::kCubicParabola: return "cubic";
    case SegmentKind::kSpline: return "spline";
  }
  return "?";
}

Segment Segment::line(Vec2 from, Vec2 to) {
  Segment s;
  s.kind_ = SegmentKind::kLine;
  s.c_[0] = from;
  s.c_[1] = to - from;
  return s;
}

Segment Segment::arc(Vec2 centre, double radius, double start_angle, double sweep) {
  Segment s;
  s.kind_ = SegmentKind::kArc;
  s.centre_ = centre;
  s.radius_ = radius;
  s.angle0_ = start_angle;
  s.sweep_ = sweep;
  return s;
}

Segment Segment::cubic_parabola(double a, double b, double c, double d, double x_from,
                                double x_to) {
  // Substitute x = x0 + h u and expand in powers of u.
  const double x0 = x_from, h = x_to - x_from;
  Segment s;
  s.kind_ = SegmentKind::kCubicParabola;
  s.c_[0] = {x0, ((a * x0 + b) * x0 + c) * x0 + d};
  s.c_[1] = {h, (3 * a * x0 * x0 + 2 * b * x0 + c) * h};
  s.c_[2] = {0.0, (3 * a * x0 + b) * h * h};
  s.c_[3] = {0.0, a * h * h * h};
  return s;
}

Segment Segment::cubic_parabola_local(double x0, double h, double e0, double e1, double e2,
                                      double e3) {
  Segment s;
  s.kind_ = SegmentKind::kCubicParabola;
  s.c_[0] = {x0, e0};
  s.c_[1] = {h, e1};
  s.c_[2] = {0.0, e2};
  s.c_[3] = {0.0, e3};
  return s;
}

Segment Segment::spline(Vec2 c0, Vec2 c1, Vec2 c2, Vec2 c3) {
  Segment s;
  s.kind_ = SegmentKind::kSpline;
  s.c_[0] = c0;
  s.c_[1] = c1;
  s.c_[2] = c2;
  s.c_[3] = c3;
  return s;
}

CurvePoint Segment::eval(double u) const {
  if (kind_ == SegmentKind::kArc) {
    const double th = angle0_ + sweep_ * u;
    const double c = std::cos(th), s = std::sin(th);
    const double rw = radius_ * sweep_;
    return {{centre_.x + radius_ * c, centre_.y + radius_ * s},
            {-rw * s, rw * c},
            {-rw * sweep_ * c, -rw * sweep_ * s}};
  }
  const Vec2* c = c_;
  return {c[0] + u * (c[1] + u * (c[2] + u * c[3])), c[1] + u * (2.0 * c[2] + 3.0 * u * c[3]),
          2.0 * c[2] + 6.0 * u * c[3]};
}

Vec2 Segment::point(double u) const {
  if (kind_ == SegmentKind::kArc) {
    const double th = angle0_ + sweep_ * u;
    return {centre_.x + radius_ * std::cos(th), centre_.y + radius_ * std::sin(th)};
  }
  return c_[0] + u * (c_[1] + u * (c_[2] + u * c_[3]));
}

int Segment::tangent_parallel(Vec2 dir, double u0, double u1, double out[4]) const {
  int n = 0;
  auto keep = [&](double u) {
    if (u > u0 && u < u1 && n < 4) out[n++] = u;
  };
  if (kind_ == SegmentKind::kArc) {
    // dp/du is perpendicular to the radius: parallel to dir where the radius is normal to
    // dir, i.e. at the angles of dir +- 90 degrees.
    const double base = std::atan2(dir.y, dir.x) + M_PI / 2;
    if (sweep_ == 0.0) return 0;
    for (int k = -8; k <= 8; ++k) {
      keep((base + k * M_PI - angle0_) / sweep_);
    }
    std::sort(out, out + n);
    return n;
  }
  // cross(dp/du, dir) = 0 is a quadratic in u.
  const double a = 3.0 * cross(c_[3], dir), b = 2.0 * cross(c_[2], dir), c = cross(c_[1], dir);
  const double scale = std::fabs(a) + std::fabs(b) + std::fabs(c);
  if (scale == 0.0) return 0;
  if (std::fabs(a) <= 1e-14 * scale) {
    if (std::fabs(b) > 1e-14 * scale) keep(-c / b);
    return n;
  }
  const double disc = b * b - 4 * a * c;
  if (disc < 0) return 0;
  const double q = -0.5 * (b + std::copysign(std::sqrt(disc), b));
  double r1 = q / a, r2 = q != 0.0 ? c / q : r1;
  if (r1 > r2) std::swap(r1, r2);
  keep(r1);
  if (r2 != r1) keep(r2);
  return n;
}

Segment Segment::scaled(double s) const {
  Segment r = *this;
  for (auto& c : r.c_) c = s * c;
  r.centre_ = s * centre_;
  r.radius_ = s * radius_;
  return r;
}

}  // namespace ncinterp::firststage
