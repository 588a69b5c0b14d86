// Cutter-centre path (Tamm, "On the cutter centre trajectory"): each chord's line is moved
// by the cutter radius R along its normal (the normal form of the line set equal to +-R)
// and neighbouring offset lines are intersected.
// Sign rule: the paper picks +R or -R per line from the traversal direction (clockwise),
// outside/inside milling and whether the ordinate grows; with the normal taken as the left
// normal of the direction of travel the same rule reads: +R when the cutter is on the left
// (G41 sense), -R on the right (G42), for every line.
// Corners: at a convex vertex (the path turns away from the cutter) turning by at most 90
// degrees the two offset lines are intersected (the cutter touches both chords to their
// ends: the part is exactly the chord polygon); beyond 90 degrees the centre goes around
// the vertex on a polygon circumscribed about the circle of radius R (every vertex again an
// intersection of tangent lines, each turning <= 90 degrees), so it never runs far out at
// sharp corners such as a trailing edge. At a concave vertex the offset lines are
// intersected before their ends (trimmed): the cutter touches both chords and cannot cut
// into either (no gouge). A trimmed offset line whose direction reverses (the chord is
// shorter than the cutter can follow) is dropped and its neighbours intersected. At the
// ends of an open chain the path starts and ends on the normal offset of the chain's end
// points; if the first or last line reverses there, it is dropped too and the path starts
// (ends) where its neighbour's offset meets its offset, so the cutter never backs up into
// the chord before it.
#pragma once
#include <vector>

#include "firststage.h"

namespace ncinterp::firststage {

struct CutterOffsetOptions {
  double radius = 0.0;  // BLU
  bool left = true;     // cutter on the left of the direction of travel
};

// Offsets the cutting moves (lines) of the path from `start`; rapid moves are re-aimed at
// the offset chains. *new_start receives the offset path's start. Throws
// std::runtime_error for arc moves (use --arcs chords with a cutter radius).
std::vector<Move> offset_moves(GridPoint start, const std::vector<Move>& moves,
                               const CutterOffsetOptions& options, GridPoint* new_start,
                               long* dropped = nullptr);

}  // namespace ncinterp::firststage
