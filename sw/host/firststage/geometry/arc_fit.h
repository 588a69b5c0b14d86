// Circular arcs from the way inputs state them (start, end, centre or radius, direction).
// Idea: written coordinates are rounded, so the end is rarely exactly on the circle about
// the written centre. The arc is made a true circle through both endpoints by moving the
// centre to the nearest point of their perpendicular bisector; the caller rejects arcs
// whose end is farther off the circle than its tolerance (arc_radius_mismatch).
#pragma once
#include "geometry/segment.h"

namespace ncinterp::firststage {

// |(|end - centre|) - (|start - centre|)|: how far the end is off the start's circle.
double arc_radius_mismatch(Vec2 start, Vec2 end, Vec2 centre);
// Arc from start to end about (nearly) centre; a full circle when start == end.
Segment arc_through(Vec2 start, Vec2 end, Vec2 centre, bool ccw);
// Centre of the arc of signed radius r (r < 0: the arc longer than half a circle), as in
// G-code R words; false when the endpoints are farther apart than 2|r| (or coincide).
bool arc_centre_from_radius(Vec2 start, Vec2 end, double r, bool ccw, Vec2* centre);

}  // namespace ncinterp::firststage
