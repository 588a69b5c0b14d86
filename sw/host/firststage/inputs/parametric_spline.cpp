// Natural parametric cubic spline (see parametric_spline.h).
#include "inputs/parametric_spline.h"

namespace ncinterp::firststage {

std::vector<Segment> natural_spline(const std::vector<Vec2>& p) {
  const size_t n = p.size();
  std::vector<Segment> out;
  if (n < 2) return out;
  std::vector<double> h(n - 1);
  for (size_t i = 0; i + 1 < n; ++i) h[i] = norm(p[i + 1] - p[i]);
  // Second derivatives M_i: h_{i-1} M_{i-1} + 2(h_{i-1}+h_i) M_i + h_i M_{i+1} = 6 (s_i - s_{i-1}).
  std::vector<Vec2> m(n), rhs(n);
  std::vector<double> diag(n, 1.0), upper(n, 0.0), lower(n, 0.0);
  for (size_t i = 1; i + 1 < n; ++i) {
    lower[i] = h[i - 1];
    diag[i] = 2.0 * (h[i - 1] + h[i]);
    upper[i] = h[i];
    rhs[i] = 6.0 * ((1.0 / h[i]) * (p[i + 1] - p[i]) - (1.0 / h[i - 1]) * (p[i] - p[i - 1]));
  }
  for (size_t i = 1; i < n; ++i) {  // forward elimination
    const double w = lower[i] / diag[i - 1];
    diag[i] -= w * upper[i - 1];
    rhs[i] = rhs[i] - w * rhs[i - 1];
  }
  m[n - 1] = (1.0 / diag[n - 1]) * rhs[n - 1];
  for (size_t i = n - 1; i-- > 0;) m[i] = (1.0 / diag[i]) * (rhs[i] - upper[i] * m[i + 1]);
  for (size_t i = 0; i + 1 < n; ++i) {
    const double hi = h[i];
    const Vec2 slope = (1.0 / hi) * (p[i + 1] - p[i]) - (hi / 6.0) * (2.0 * m[i] + m[i + 1]);
    out.push_back(Segment::spline(p[i], hi * slope, (0.5 * hi * hi) * m[i],
                                  (hi * hi / 6.0) * (m[i + 1] - m[i])));
  }
  return out;
}

}  // namespace ncinterp::firststage
