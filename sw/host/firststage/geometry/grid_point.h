// A point of the BLU grid: where every chord end and every tape position lies.
// Idea: the first stage rounds chord ends to it, the checker integrates pulses and places
// programmed blocks on it; one struct for both (integers, so equality is exact).
#pragma once
#include <cstdint>

#include "geometry/vec2.h"

namespace ncinterp::firststage {

struct GridPoint {
  int64_t x = 0, y = 0;  // BLU
  bool operator==(const GridPoint& o) const { return x == o.x && y == o.y; }
  bool operator!=(const GridPoint& o) const { return !(*this == o); }
};
inline Vec2 to_vec(GridPoint g) { return {static_cast<double>(g.x), static_cast<double>(g.y)}; }

}  // namespace ncinterp::firststage
