// How far a chord is from the curve it replaces, measured as Kolesnikov does: along the
// curve's normal (paper 004, eqs. 1-6), and where a chord's end lies on the curve (foot).
// Idea: for a curve point C(t) the normal meets the chord line at signed distance
// beta(t) = -nu.(C(t) - P) / (nu.n(t)) (nu: the chord's unit normal, n: the curve's).
// beta is stationary only where the tangent is parallel to the chord (eq. 16; the other
// factor, eq. 17, needs the chord through the centre of curvature). So the maximum over a
// chord is exact from a handful of points: both ends, every tangent-parallel point (closed
// form per segment) and both sides of every joint. No sampling, no iteration.
#pragma once
#include <limits>

#include "chords/span.h"

namespace ncinterp::firststage {

constexpr double kInvalidDeviation = std::numeric_limits<double>::infinity();

// Max |beta| of chord P->Q over the curve parameters [ta, tb] (ta, tb: feet of P and Q),
// also at least the distances |P - C(ta)| and |Q - C(tb)|. Infinity when the chord is
// not roughly along the curve (normals more than 60 degrees off) or has zero length.
double chord_deviation(const Span& span, Vec2 p, Vec2 q, double ta, double tb);

// Parameter t in [lo, hi] of the curve point nearest q (its normal passes through q),
// searched from guess.
double foot_parameter(const Span& span, Vec2 q, double guess, double lo, double hi);

}  // namespace ncinterp::firststage
