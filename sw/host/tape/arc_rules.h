// The rules an arc block must keep (docs/circle-dda.md section 2), for the tape reader and
// writer: zero radius, inside one quadrant, end inside the register, end on the circle.
// Idea: written independently of the interpolator's decoder (rtl/arc_geometry.sv,
// sc_model/golden/arc_geometry.cpp) so the cross-check of reader and decoder on damaged
// tapes (tests/sw/host/tape) tests both.
#pragma once
#include <cstdint>
#include <string>

#include "tape.h"

namespace ncinterp::tape {

// The first rule an arc block breaks, in the decoder's order, as the interpolator's error
// code (zero radius, not inside one quadrant, end beyond the register, end off the circle)
// and a message; TapeError::kNone for a good arc.
struct ArcRuleBroken {
  TapeError code = TapeError::kNone;
  std::string message;
};
ArcRuleBroken broken_arc_rule(const Block& b, uint64_t inc_max);

}  // namespace ncinterp::tape
