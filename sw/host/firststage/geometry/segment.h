// One piece of a part contour: a parametric cubic (lines, cubic parabolas y = f(x) and
// airfoil spline pieces all are one) or a circular arc, with parameter u in [0, 1].
// Idea: every chord method only needs the point, its first and second derivatives and the
// parameters where the tangent is parallel to a given direction (Kolesnikov's condition
// for the maximum normal error of a chord, eq. 16). Both kinds give those in closed form,
// so one curve interface serves every segment type.
#pragma once
#include <string>

#include "geometry/vec2.h"

namespace ncinterp::firststage {

enum class SegmentKind { kLine, kArc, kCubicParabola, kSpline };

const char* segment_kind_name(SegmentKind kind);

struct CurvePoint {
  Vec2 p, d1, d2;  // point, dp/du, d2p/du2
};

class Segment {
 public:
  static Segment line(Vec2 from, Vec2 to);
  // Circle through `from` about `centre`, sweeping `sweep` radians (> 0 counter-clockwise).
  static Segment arc(Vec2 centre, double radius, double start_angle, double sweep);
  // y = a x^3 + b x^2 + c x + d for x from x_from to x_to (either direction).
  static Segment cubic_parabola(double a, double b, double c, double d, double x_from,
                                double x_to);
  // The same with y written about the span start: x = x0 + h u,
  // y = e0 + e1 u + e2 u^2 + e3 u^3 (how reference-point tables build their spans).
  static Segment cubic_parabola_local(double x0, double h, double e0, double e1, double e2,
                                      double e3);
  // p(u) = c0 + c1 u + c2 u^2 + c3 u^3.
  static Segment spline(Vec2 c0, Vec2 c1, Vec2 c2, Vec2 c3);

  SegmentKind kind() const { return kind_; }
  bool is_arc() const { return kind_ == SegmentKind::kArc; }
  CurvePoint eval(double u) const;
  Vec2 point(double u) const;
  Vec2 start() const { return point(0.0); }
  Vec2 end() const { return point(1.0); }
  // Parameters u in [u0, u1] where dp/du is parallel (or antiparallel) to dir; at most 4.
  int tangent_parallel(Vec2 dir, double u0, double u1, double out[4]) const;
  // The same geometry with every coordinate multiplied by s (mm -> BLU).
  Segment scaled(double s) const;

  // Arc data (valid when is_arc()).
  Vec2 centre() const { return centre_; }
  double radius() const { return radius_; }
  double start_angle() const { return angle0_; }
  double sweep() const { return sweep_; }

  // Where the segment came from: input line (1-based, 0 = none) and index of the input
  // element it belongs to (a table or spline expands into several segments).
  int source_line = 0;
  int source_index = 0;
  // A rapid move (G0): emitted as a line, never part of a cutting contour.
  bool rapid = false;

 private:
  SegmentKind kind_ = SegmentKind::kLine;
  Vec2 c_[4];  // polynomial coefficients (line, cubic parabola, spline)
  Vec2 centre_;
  double radius_ = 0.0, angle0_ = 0.0, sweep_ = 0.0;
};

}  // namespace ncinterp::firststage
