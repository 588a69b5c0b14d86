// Circular arcs as arc blocks (--arcs circle): split at the quadrant boundaries about the
// centre, every end on the BLU grid, as the interpolator requires (docs/first-stage.md).
// Idea: the block centre is one grid point near the true centre, chosen so the start and
// end grid points are (nearly) equally far from it; the boundary points lie exactly on the
// axes through it at the rounded radius, so each block's end radius is within 1 BLU of its
// start radius (checked; else the arc is chorded instead).
#pragma once
#include <vector>

#include "firststage.h"

namespace ncinterp::firststage {

// Appends the quadrant arc moves for `arc` (BLU units) from grid point `start` (the arc's
// rounded start) to the arc's rounded end. Returns false, appending nothing, when arc
// blocks cannot hold it within `max_dev` BLU of the true circle or within the registers.
bool quadrant_arcs(const Segment& arc, GridPoint start, int64_t max_inc, double max_dev,
                   int element, std::vector<Move>& out);

}  // namespace ncinterp::firststage
