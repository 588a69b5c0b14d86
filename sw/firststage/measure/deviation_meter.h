// Measures how far a tape path is from its contour, independently of the chord methods:
// both are sampled densely (a fixed step in mm) and every sample's Euclidean distance to
// the other polyline is found through a uniform grid of cells. The larger of the two
// directions is the path's deviation (a Hausdorff distance); it goes into the report.
#pragma once
#include <vector>

#include "firststage.h"

namespace ncinterp::firststage {

struct DeviationReport {
  double max_mm = 0.0;                // max of the two below
  double path_to_contour_mm = 0.0;    // farthest path sample from the contour
  double contour_to_path_mm = 0.0;    // farthest contour sample from the path
  long samples = 0;
};

// Contour (mm) against the path of `moves` from `start` (BLU). Rapid segments and rapid
// moves are left out on both sides. step_mm: sampling step (use <= tol / 4).
DeviationReport measure_deviation(const Contour& contour, GridPoint start,
                                  const std::vector<Move>& moves, double blu_mm, double step_mm);

}  // namespace ncinterp::firststage
