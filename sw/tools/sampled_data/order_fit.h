// The order p and constant c of an error law e = c h^p, fitted to measurements.
// Idea: least squares on log10 e = log10 c + p log10 h; points with e <= 0 carry no
// information on a log scale and are left out by the caller.
#pragma once
#include <vector>

namespace ncinterp::sampled {

struct OrderFit {
  bool valid = false;  // at least two points with different h
  double order = 0;    // p
  double constant = 0; // c
  int points = 0;
  double h_min = 0, h_max = 0;
  double max_residual_decades = 0;  // largest |log10 e - fitted| over the points
};

OrderFit fit_order(const std::vector<double>& h, const std::vector<double>& error);

}  // namespace ncinterp::sampled
