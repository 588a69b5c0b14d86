// The update-scheme study behind the circle DDA (docs/circle-dda.md 3.1): a free-running
// signed DDA circle generator, without pulse counters or quadrant blocks, run for whole
// turns, to show whether its error grows with the number of turns.
// Idea: the same integer integrators as rtl/dda_circle.sv (modulus 2^k, k = bit length of
// R, integrators starting at half), in signed form so the circle can go round and round:
// the X integrator adds -y, the Y integrator adds +x (counter-clockwise); a carry out of
// [0, 2^k) is a step up, a borrow a step down. Three schemes:
//   simultaneous:  both integrators use the coordinates before the iteration (forward Euler)
//   x_first:       X steps first, Y then integrates the new x (immediate, semi-implicit)
//   alternating:   as x_first, but the order alternates every iteration (what the RTL does)
// A radius that grows past 2^k makes one iteration carry more than once; the study allows
// that (the hardware could not), so forward Euler can be followed for ten turns.
#pragma once
#include <cstdint>

namespace ncinterp::circle_study {

enum class Scheme { kSimultaneous, kXFirst, kAlternating };

const char* scheme_name(Scheme s);

struct TurnStats {
  double max_radial_error = 0;  // at every position after a pulse, vs the start radius
  int64_t end_x = 0, end_y = 0; // where the turn ended (first position back in quadrant 1)
  uint64_t iterations = 0;
};

// Runs `turns` counter-clockwise turns from (radius, 0); fills one TurnStats per turn.
void run_free_turns(Scheme scheme, int64_t radius, int turns, TurnStats* per_turn);

}  // namespace ncinterp::circle_study
