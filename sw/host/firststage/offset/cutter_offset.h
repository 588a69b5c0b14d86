// Cutter-centre path (Tamm, "On the cutter centre trajectory"): each chord's line is moved
// by the cutter radius R along its normal (the normal form of the line set equal to +-R)
// and neighbouring offset lines are intersected.
// Sign rule: the paper picks +R or -R per line from the traversal direction (clockwise),
// outside/inside milling and whether the ordinate grows; with the normal taken as the left
// normal of the direction of travel the same rule reads: +R when the cutter is on the left
// (G41 sense), -R on the right (G42), for every line.
// The path is the edge, on the cutter's side, of the region nearer than R to the chain (the
// union of discs of radius R about the chords): offset segments, and arcs of radius R about
// convex vertices; where two offset segments cross at a concave corner the edge turns from
// one onto the other (neighbouring offset lines intersected, as in the paper), and chords the
// cutter cannot follow (shorter than the trim at a sharp concave corner, walls of a notch
// narrower than 2R) are simply not on it. Nothing on that edge is nearer than R to a chord:
// no gouge, by construction.
// Convex corners: up to a 90-degree turn the two offset lines are intersected (the cutter
// touches both chords to their ends: the part is exactly the chord polygon); beyond 90
// degrees the centre goes around the vertex on a polygon circumscribed about the circle of
// radius R (every vertex again an intersection of tangent lines, each turning <= 90
// degrees), so it never runs far out at sharp corners such as a trailing edge. An open
// chain's path starts and ends on the circles about its end points, where the offsets of
// the first and last chords that are on the edge meet them.
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
                               const CutterOffsetOptions& options, GridPoint* new_start);

}  // namespace ncinterp::firststage
