// C2 interpolating cubic spline through a point sequence, parametric in chord length, as
// contour segments (one cubic piece per interval). Natural ends (zero second derivative):
// the ends are corners of the contour, so nothing is assumed beyond them.
// Idea: x is not monotonic around an airfoil's leading edge, so y(x) cannot be used; each
// coordinate is a spline in the cumulative chord length t, solved by the tridiagonal
// (Thomas) algorithm for the second derivatives.
#pragma once
#include <vector>

#include "geometry/segment.h"

namespace ncinterp::firststage {

std::vector<Segment> natural_spline(const std::vector<Vec2>& points);

}  // namespace ncinterp::firststage
