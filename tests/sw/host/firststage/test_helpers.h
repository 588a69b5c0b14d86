// Helpers for the first-stage tests: contours built in code, the tape path in mm and the
// true curve as a dense polyline (from the analytic formula, not from the code under test).
#pragma once
#include <cmath>
#include <functional>
#include <string>
#include <vector>

#include "firststage.h"
#include "independent_checker.h"

namespace ncinterp::test {

using firststage::Contour;
using firststage::FirstStageOptions;
using firststage::FirstStageResult;
using firststage::Move;
using firststage::MoveKind;
using firststage::Segment;
using firststage::Vec2;

// The path of `moves` from `start` in mm, one polyline per cutting chain (a rapid move
// ends a chain and is not part of any). Lines are their end points; an arc block is
// sampled every `arc_step` mm on the circle through its start about its centre (the circle
// the interpolator's circle DDA follows, within 1 BLU: docs/circle-dda.md), and its grid
// end point is appended.
inline std::vector<std::vector<P2>> path_chains_mm(firststage::GridPoint start,
                                                   const std::vector<Move>& moves, double blu,
                                                   double arc_step = 0.001) {
  std::vector<std::vector<P2>> chains(1);
  P2 cur{start.x * blu, start.y * blu};
  chains.back().push_back(cur);
  for (const Move& m : moves) {
    const P2 to{m.to.x * blu, m.to.y * blu};
    if (m.rapid) {
      if (chains.back().size() < 2) chains.back().clear();
      else chains.emplace_back();
      chains.back().push_back(to);
      cur = to;
      continue;
    }
    if (m.kind != MoveKind::kLine) {
      const P2 c{m.centre.x * blu, m.centre.y * blu};
      const double r0 = std::hypot(cur.x - c.x, cur.y - c.y);
      const double a0 = std::atan2(cur.y - c.y, cur.x - c.x);
      double sweep = std::atan2(to.y - c.y, to.x - c.x) - a0;
      if (m.kind == MoveKind::kArcCcw && sweep <= 0) sweep += 2 * M_PI;
      if (m.kind == MoveKind::kArcCw && sweep >= 0) sweep -= 2 * M_PI;
      const long n = static_cast<long>(std::fabs(sweep) * r0 / arc_step) + 1;
      for (long i = 1; i < n; ++i) {
        const double a = a0 + sweep * static_cast<double>(i) / n;
        chains.back().push_back({c.x + r0 * std::cos(a), c.y + r0 * std::sin(a)});
      }
    }
    chains.back().push_back(to);
    cur = to;
  }
  if (chains.back().size() < 2) chains.pop_back();
  return chains;
}

// The whole tape path as one polyline (contours without rapid moves).
inline std::vector<P2> path_mm(const FirstStageResult& r, double blu) {
  std::vector<P2> out;
  for (const auto& chain : path_chains_mm(r.start, r.moves, blu))
    out.insert(out.end(), chain.begin(), chain.end());
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
  return firststage::contour_from_segments("test", origin, std::move(segs));
}

}  // namespace ncinterp::test
