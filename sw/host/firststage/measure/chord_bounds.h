// Reference chord counts to judge the methods against (docs/first-stage.md):
//  - the two-sided lower bound: a chord two-sided within delta over a curve of curvature
//    kappa is at most 4 sqrt(delta / kappa) long, so at least  int sqrt(kappa / (16 delta)) ds
//    chords are needed (integrated numerically over every curved segment);
//  - grbl's arc rule (one-sided, arcs only): floor(|theta| R / 2 / sqrt(delta (2R - delta)))
//    segments per arc, at least 1.
#pragma once
#include "geometry/contour.h"

namespace ncinterp::firststage {

double two_sided_lower_bound(const Contour& contour, double delta_mm);
// Sum over the contour's arcs (other segment kinds: 0); arcs_counted receives how many.
long grbl_arc_segments(const Contour& contour, double delta_mm, int* arcs_counted = nullptr);

}  // namespace ncinterp::firststage
