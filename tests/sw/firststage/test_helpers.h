// Helpers for the first-stage tests: contours built in code, the tape path in mm and the
// true curve as a dense polyline (from the analytic formula, not from the code under test).
#pragma once
#include <cmath>
#include <functional>
#include <vector>

#include "firststage.h"
#include "independent_checker.h"

namespace ncinterp::test {

using firststage::Contour;
using firststage::FirstStageOptions;
using firststage::FirstStageResult;
using firststage::Segment;
using firststage::Vec2;

// Path of the result's moves in mm (line moves only; arcs are sampled as their circle).
inline std::vector<P2> path_mm(const FirstStageResult& r, double blu) {
  std::vector<P2> out{{r.start.x * blu, r.start.y * blu}};
  for (const auto& m : r.moves) out.push_back({m.to.x * blu, m.to.y * blu});
  return out;
}

// Dense samples of a curve given as a function of s in [0, 1].
inline std::vector<P2> sample_curve(const std::function<P2(double)>& f, long n) {
  std::vector<P2> out;
  out.reserve(n + 1);
  for (long i = 0; i <= n; ++i) out.push_back(f(static_cast<double>(i) / n));
  return out;
}

inline Contour contour_of(Vec2 origin, std::vector<Segment> segs) {
  Contour c;
  c.file = "test";
  c.origin = origin;
  for (size_t i = 0; i < segs.size(); ++i) {
    segs[i].source_index = static_cast<int>(i);
    c.element_names.push_back("segment " + std::to_string(i));
  }
  c.segments = std::move(segs);
  return c;
}

}  // namespace ncinterp::test
