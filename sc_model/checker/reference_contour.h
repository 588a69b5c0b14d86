// The contour the tool must follow, as the checker measures the total error against it.
// Idea: the part contour from the first stage's reader (mm) is scaled to BLU and placed so
// that the tape start, where the position counters read (0, 0), sits at its absolute grid
// point. Without a cutter radius the total error of a tool position is its distance from
// the contour along the contour's normal (ContourDistance). With a cutter radius R the tool
// centre must run on the offset contour (the equidistant at R on the cutter's side), so
// the total error is |d - R| with d the distance to the part contour; d - R < 0 means the
// cutter cuts into the part (gouge). At a convex corner of the part the first stage takes
// the centre around the corner outside the equidistant on purpose (the cutter touches both
// sides to the vertex and leaves the corner sharp): a position whose nearest part point is
// such a corner vertex and which is farther than R counts as a corner excursion, reported
// apart, not as error. Traverses are not cut: the tape says which blocks they are (G00),
// and the checker measures no total error on them; the input's rapid moves are kept here
// only to be drawn.
#pragma once
#include <string>
#include <vector>

#include "contour_distance.h"
#include "geometry/contour.h"
#include "programmed_path.h"

namespace ncinterp::checker {

struct ReferenceOptions {
  double blu_mm = 0.001;
  GridPoint start;               // absolute grid point (BLU) of the tape start
  double cutter_radius_mm = 0.0; // 0: the tape is the contour itself
  bool cutter_left = true;       // cutter on the left of the direction of travel
};

struct TotalError {
  double error = 0.0;      // BLU: |d| (no offset) or |d - R|
  double signed_excess = 0.0;  // d - R (offset) or d, BLU
  bool outside = false;    // offset only: d > R at a foot the cutter reaches from elsewhere
  int segment = -1;        // contour segment of the foot
  Vec2 foot;               // relative to the tape start, BLU
};

class ReferenceContour {
 public:
  ReferenceContour(const firststage::Contour& contour, const ReferenceOptions& options);

  // The programmed cutter path (offset case): the blocks but the traverses (G00), with
  // their bounds.
  void set_tool_path(const std::vector<ProgrammedBlock>& blocks, const std::vector<bool>& rapid,
                     const std::vector<double>& bounds);
  // Total error of a tool position (relative to the tape start, BLU).
  TotalError measure(Vec2 position) const;
  // Name of the input element a contour segment belongs to ("line 12 (G2)" ...).
  std::string element_name(int segment) const;
  // The cutting and rapid segments in absolute BLU (subtract start() for positions), for plots.
  const std::vector<firststage::Segment>& cutting_segments() const { return cut_.segments(); }
  const std::vector<firststage::Segment>& rapid_segments() const { return rapids_; }
  double radius_blu() const { return radius_; }
  bool cutter_left() const { return options_.cutter_left; }
  GridPoint start() const { return options_.start; }

 private:
  TotalError centre_only(Vec2 position) const;  // e = d - R, without the path

  ReferenceOptions options_;
  double radius_ = 0.0;  // BLU
  ContourDistance cut_;
  std::vector<firststage::Segment> rapids_;
  std::vector<std::string> names_;     // per cutting segment
  ContourDistance path_{std::vector<Segment>{}};  // the programmed cutter path, absolute BLU
  std::vector<double> path_bound_;     // per path segment: interpolator bound, BLU
};

}  // namespace ncinterp::checker
