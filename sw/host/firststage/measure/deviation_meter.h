// Measures how far a tape path is from its contour, independently of the chord methods:
// both are sampled densely (a fixed step in mm), and for each the largest Euclidean distance
// from one of its samples to the polyline through the other's samples is found. The larger
// of the two directions is the path's deviation (a Hausdorff distance); it goes into the
// report.
// Idea: only the maximum is wanted. Samples are made one at a time, in order, and each is
// first measured against the few segments near the previous sample's nearest one; that is
// an upper bound, and a sample whose bound is at or below the running maximum cannot raise
// it. Only the others are measured exactly, through a grid of cells holding chunks of the
// other polyline. Straight moves and lines are held as the segments they are; a curve's
// sample points are computed again when a chunk is needed, never stored. The result is the
// one of measuring every sample exactly, in about linear time and with memory for the
// chunks only (about one per 128 samples).
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
