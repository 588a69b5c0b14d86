// Distance from a point to a part contour, along the contour's normal (Kolesnikov's measure),
// computed independently of the chord methods.
// Idea: the nearest point of a smooth curve to q is where the line from q meets the curve
// at a right angle, so the closest-point distance IS the distance along the normal through
// q. Lines and arcs have it in closed form. Cubic pieces (cubic parabolas, airfoil spline
// pieces) are searched by branch and bound over their Bezier form: a piece lies inside the
// convex hull of its control points, so the distance to the chord b0-b3 minus the hull's
// width is a lower bound and any curve point gives an upper bound; pieces whose lower bound
// cannot beat the best upper bound are dropped, the rest are halved (de Casteljau) until
// the bracket is narrower than kDistanceAccuracy. The result is therefore certified: the
// true distance lies in [distance - kDistanceAccuracy, distance], never above the reported
// value, whatever the curve's shape (no starting guess, no Newton step that can miss a
// branch). Which segments to search comes from a spatial index of their bounding boxes
// (Boost.Geometry's R-tree) and a candidate list kept between queries: around a point q0
// with an upper bound U of its distance, every segment whose box is within U + 2m of q0 is
// a candidate; for any q within m of q0 the nearest segment is among them (a segment whose
// box is farther than U + 2m from q0 is farther than U + m from q, and the nearest is
// within U + m). Pulses move one BLU at a time, so the list serves about m pulses and a
// query costs a few exact segment distances whatever the contour's length.
#pragma once
#include <memory>
#include <vector>

#include "geometry/segment.h"

namespace ncinterp::checker {

using firststage::Segment;
using firststage::Vec2;

// Certified accuracy of every distance, in the contour's units (the checker works in BLU:
// 1e-4 BLU = 0.1 nm at BLU 0.001 mm).
constexpr double kDistanceAccuracy = 1e-4;

struct ContourFoot {
  double distance = 0.0;  // |q - foot|, within kDistanceAccuracy above the true minimum
  int segment = -1;       // index into the segments given to ContourDistance
  double u = 0.0;         // parameter of the foot on that segment
  Vec2 foot;
};

class ContourDistance {
 public:
  // The segments, in the units the queries use (the checker scales mm to BLU first).
  explicit ContourDistance(std::vector<Segment> segments);

  bool empty() const { return pieces_.empty(); }
  const std::vector<Segment>& segments() const { return segments_; }
  // Nearest point of all segments to q.
  ContourFoot nearest(Vec2 q) const;
  // Nearest point of one segment to q.
  ContourFoot nearest_on(int segment, Vec2 q) const;

 private:
  struct Box {
    double x0, y0, x1, y1;
    double distance_sq(Vec2 q) const;  // squared distance from q (0 inside)
  };
  struct Piece {
    Box box;
    Vec2 bezier[4];  // cubic pieces: Bezier control points (u in [0, 1])
  };
  struct Index;  // the R-tree of the segments' boxes (contour_distance.cpp)
  void build_pieces();  // pieces_ from segments_
  // The candidates around q (see above).
  void refresh_candidates(Vec2 q) const;
  // Updates best with segment s if it is nearer.
  void search(int s, Vec2 q, ContourFoot& best) const;
  void search_cubic(int s, Vec2 q, ContourFoot& best) const;
  void search_arc(int s, Vec2 q, ContourFoot& best) const;

  std::vector<Segment> segments_;
  std::vector<Piece> pieces_;
  std::shared_ptr<const Index> index_;  // immutable: copies share it
  // The candidate list: its centre q0, its reach m, the segments; and the segment of the
  // last answer (a good first upper bound when the list is made again).
  mutable std::vector<int> candidates_;
  mutable Vec2 centre_;
  mutable bool have_candidates_ = false;
  mutable int hint_ = 0;
};

using firststage::distance_to_segment;

}  // namespace ncinterp::checker
