// A reference point as a real number pair, whatever arithmetic computed it, and how far
// apart two runs of the same method are (fixed point against double).
#pragma once
#include <algorithm>
#include <cmath>
#include <vector>

namespace ncinterp::sampled {

struct RealPoint {
  long double x = 0, y = 0;
};

// Largest distance between corresponding points of two runs (over the shorter one).
inline double max_distance(const std::vector<RealPoint>& a, const std::vector<RealPoint>& b) {
  double d = 0;
  for (size_t i = 0; i < std::min(a.size(), b.size()); ++i)
    d = std::max(d, static_cast<double>(std::hypot(a[i].x - b[i].x, a[i].y - b[i].y)));
  return d;
}

}  // namespace ncinterp::sampled
