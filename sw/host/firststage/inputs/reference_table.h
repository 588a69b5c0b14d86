// Reference-point tables as the designers of Tamm's time give a profile: abscissae
// x_k = x0 + k h at equal spacing, ordinates y_k, and their 1st, 2nd and 3rd differences.
// Idea: each span [x_k, x_k+1] becomes the cubic through four neighbouring reference
// points, centred where possible (Bessel): points k-1..k+2, i.e. from
// dy_k, the mean of d2y_k-1 and d2y_k, and d3y_k-1. The first span uses points 0..3, the
// last n-4..n-1 (Newton forward/backward). docs/inputs.md gives the formulas.
#pragma once
#include <vector>

#include "geometry/segment.h"

namespace ncinterp::firststage {

struct TableSpanCubic {
  double a = 0, b = 0, c = 0, d = 0;  // y = a x^3 + b x^2 + c x + d on the span
  double x_from = 0, x_to = 0;
  int first_point = 0;  // index of the first of the four points the cubic goes through
};

// Differences of order 1..3 of the ordinates: diff[m][k] = Delta^m y_k.
std::vector<std::vector<double>> table_differences(const std::vector<double>& y);
// Span cubics of a table with n >= 4 ordinates (n - 1 spans).
std::vector<TableSpanCubic> table_span_cubics(double x0, double h, const std::vector<double>& y);
// The same spans as contour segments (exact local form, no loss for large x).
std::vector<Segment> table_segments(double x0, double h, const std::vector<double>& y);

}  // namespace ncinterp::firststage
