// The rules of an arc block (see arc_rules.h).
#include "arc_rules.h"

#include <cstdlib>

namespace ncinterp::tape {

ArcRuleBroken broken_arc_rule(const Block& b, uint64_t inc_max) {
  // Coordinates relative to the centre: start (-I, -J), end (X - I, Y - J).
  if (b.i == 0 && b.j == 0)
    return {TapeError::kArcZeroRadius, "arc with zero radius: I and J are 0"};
  const int64_t x0 = -b.i, y0 = -b.j, x1 = x0 + b.dx, y1 = y0 + b.dy;
  const int turn = b.motion == Motion::kArcCcw ? 1 : -1;
  // Inside one closed quadrant (sx, sy): both ends in it, and each coordinate moves the way
  // the direction goes there (counter-clockwise: x towards -sy, y towards +sx).
  bool inside = false;
  for (int sx : {1, -1})
    for (int sy : {1, -1}) {
      const bool ends = sx * x0 >= 0 && sx * x1 >= 0 && sy * y0 >= 0 && sy * y1 >= 0;
      const bool moves = turn * sy * b.dx <= 0 && turn * sx * b.dy >= 0;
      inside = inside || (ends && moves);
    }
  if (!inside || (b.dx == 0 && b.dy == 0))
    return {TapeError::kArcCrossesQuadrant, "arc not inside one quadrant about its centre"};
  if (static_cast<uint64_t>(std::llabs(x1)) > inc_max || static_cast<uint64_t>(std::llabs(y1)) > inc_max)
    return {TapeError::kValueTooWide,
            "value too wide for its register: the arc's end about its centre exceeds " +
                std::to_string(inc_max)};
  // |R1 - R0| <= 1 exactly: with A = R0^2, B = R1^2, (B - A - 1)^2 <= 4A. |B - A - 1| beyond
  // 2^40 fails anyway (4A < 2^67) and keeps the square inside 128 bits.
  const __int128 a = __int128{x0} * x0 + __int128{y0} * y0;
  const __int128 e = __int128{x1} * x1 + __int128{y1} * y1 - a - 1;
  const __int128 mag = e < 0 ? -e : e;
  if (mag > (__int128{1} << 40) || mag * mag > 4 * a)
    return {TapeError::kArcEndpointOffCircle,
            "arc endpoint more than 1 BLU off the circle through its start"};
  return {};
}

}  // namespace ncinterp::tape
