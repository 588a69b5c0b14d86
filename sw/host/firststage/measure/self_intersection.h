// Does a tape path cross itself? A figure-eight contour, or a cutter offset larger than a
// detail of the part (the offset path loops), gives a tape the interpolator plays without
// complaint, but the part it cuts is not the one drawn. The first stage warns (it does not
// refuse: a crossing can be meant, e.g. a lead-in over the cut), docs/first-stage.md.
// Idea: sort and prune. The path's cut moves become straight pieces (an arc block as 16
// chords), sorted by their lowest x; each piece is tested only against the pieces whose x
// range overlaps its own, with exact integer orientation tests for the straight moves.
// Only proper crossings count: pieces that follow each other, touch at an end point, or
// overlap along a line (a path that goes back over itself) are not crossings.
#pragma once
#include <functional>
#include <optional>
#include <vector>

#include "firststage.h"

namespace ncinterp::firststage {

struct SelfCrossing {
  Vec2 at;                  // where, BLU
  int move_a = 0, move_b = 0;  // indices of the two moves (a < b)
};

// The first crossing found among the non-rapid moves from `start` (BLU), if any, leaving
// out those of two moves a, b where `ignore(a, b)` holds.
std::optional<SelfCrossing> find_self_crossing(GridPoint start, const std::vector<Move>& moves,
                                               const std::function<bool(int, int)>& ignore = {});

}  // namespace ncinterp::firststage
