// Log-log least-squares fit of an error law (see order_fit.h).
#include "order_fit.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace ncinterp::sampled {

OrderFit fit_order(const std::vector<double>& h, const std::vector<double>& error) {
  if (h.size() != error.size()) throw std::invalid_argument("fit_order: h and error differ in length");
  OrderFit fit;
  fit.points = static_cast<int>(h.size());
  if (h.size() < 2) return fit;
  double sx = 0, sy = 0;
  for (size_t i = 0; i < h.size(); ++i) {
    if (!(h[i] > 0) || !(error[i] > 0)) throw std::invalid_argument("fit_order: h and error must be positive");
    sx += std::log10(h[i]);
    sy += std::log10(error[i]);
  }
  const double n = static_cast<double>(h.size()), mx = sx / n, my = sy / n;
  double sxx = 0, sxy = 0;
  for (size_t i = 0; i < h.size(); ++i) {
    const double dx = std::log10(h[i]) - mx;
    sxx += dx * dx;
    sxy += dx * (std::log10(error[i]) - my);
  }
  if (sxx == 0) return fit;
  fit.valid = true;
  fit.order = sxy / sxx;
  const double log_c = my - fit.order * mx;
  fit.constant = std::pow(10.0, log_c);
  fit.h_min = *std::min_element(h.begin(), h.end());
  fit.h_max = *std::max_element(h.begin(), h.end());
  for (size_t i = 0; i < h.size(); ++i)
    fit.max_residual_decades = std::max(
        fit.max_residual_decades, std::fabs(std::log10(error[i]) - log_c - fit.order * std::log10(h[i])));
  return fit;
}

}  // namespace ncinterp::sampled
