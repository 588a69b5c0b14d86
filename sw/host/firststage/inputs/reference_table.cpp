// Reference-point table -> span cubics (see reference_table.h).
// On the span from x_k, with s = (x - x_m)/h measured from the first point m of the four,
// Newton's forward formula gives the cubic through them:
//   y = y_m + s D1 + s(s-1)/2 D2 + s(s-1)(s-2)/6 D3,  Dj = Delta^j y_m.
// For m = k - 1 this is Bessel's central formula on [x_k, x_k+1] truncated after the
// third difference.
#include "inputs/reference_table.h"

#include <algorithm>

namespace ncinterp::firststage {
namespace {

// Coefficients e0..e3 of y in powers of u = (x - x_k)/h, with c = k - m.
void span_powers(const std::vector<std::vector<double>>& diff, int m, int c, double e[4]) {
  const double y = diff[0][m], d1 = diff[1][m], d2 = diff[2][m], d3 = diff[3][m];
  // In powers of s: a0 + a1 s + a2 s^2 + a3 s^3.
  const double a0 = y, a1 = d1 - d2 / 2 + d3 / 3, a2 = d2 / 2 - d3 / 2, a3 = d3 / 6;
  // Taylor expansion about s = c (s = u + c).
  e[0] = ((a3 * c + a2) * c + a1) * c + a0;
  e[1] = (3 * a3 * c + 2 * a2) * c + a1;
  e[2] = 3 * a3 * c + a2;
  e[3] = a3;
}

int first_point_of_span(int k, int n) { return std::clamp(k - 1, 0, n - 4); }

}  // namespace

std::vector<std::vector<double>> table_differences(const std::vector<double>& y) {
  std::vector<std::vector<double>> diff{y};
  for (int m = 1; m <= 3; ++m) {
    const auto& prev = diff.back();
    std::vector<double> next;
    for (size_t k = 0; k + 1 < prev.size(); ++k) next.push_back(prev[k + 1] - prev[k]);
    diff.push_back(next);
  }
  return diff;
}

std::vector<TableSpanCubic> table_span_cubics(double x0, double h, const std::vector<double>& y) {
  const int n = static_cast<int>(y.size());
  const auto diff = table_differences(y);
  std::vector<TableSpanCubic> out;
  for (int k = 0; k + 1 < n; ++k) {
    const int m = first_point_of_span(k, n);
    double e[4];
    span_powers(diff, m, k - m, e);
    // y in powers of u = (x - xk)/h  ->  powers of x.
    const double xk = x0 + k * h;
    const double p3 = e[3] / (h * h * h), p2 = e[2] / (h * h), p1 = e[1] / h;
    TableSpanCubic s;
    s.a = p3;
    s.b = p2 - 3 * p3 * xk;
    s.c = p1 - 2 * p2 * xk + 3 * p3 * xk * xk;
    s.d = e[0] - p1 * xk + p2 * xk * xk - p3 * xk * xk * xk;
    s.x_from = xk;
    s.x_to = xk + h;
    s.first_point = m;
    out.push_back(s);
  }
  return out;
}

std::vector<Segment> table_segments(double x0, double h, const std::vector<double>& y) {
  const int n = static_cast<int>(y.size());
  const auto diff = table_differences(y);
  std::vector<Segment> out;
  for (int k = 0; k + 1 < n; ++k) {
    const int m = first_point_of_span(k, n);
    double e[4];
    span_powers(diff, m, k - m, e);
    out.push_back(Segment::cubic_parabola_local(x0 + k * h, h, e[0], e[1], e[2], e[3]));
  }
  return out;
}

}  // namespace ncinterp::firststage
