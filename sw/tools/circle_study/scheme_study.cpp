// Free-running circle DDA for the update-scheme study (see the header).
#include "scheme_study.h"

#include "bit_length.h"

#include <cmath>

namespace ncinterp::circle_study {

namespace {

// One integrator: adds `in`, steps the coordinate once per carry (or borrow).
bool integrate(int64_t& acc, int64_t in, int64_t kpow, int64_t& coord) {
  acc += in;
  bool stepped = false;
  while (acc >= kpow) {
    acc -= kpow;
    ++coord;
    stepped = true;
  }
  while (acc < 0) {
    acc += kpow;
    --coord;
    stepped = true;
  }
  return stepped;
}

}  // namespace

const char* scheme_name(Scheme s) {
  switch (s) {
    case Scheme::kSimultaneous: return "simultaneous (forward Euler)";
    case Scheme::kXFirst: return "immediate, X first";
    case Scheme::kAlternating: return "immediate, alternating (RTL)";
  }
  return "?";
}

void run_free_turns(Scheme scheme, int64_t radius, int turns, TurnStats* per_turn) {
  const int64_t kpow = int64_t{1} << bit_length(static_cast<uint64_t>(radius));
  int64_t acc_x = kpow / 2, acc_y = kpow / 2;
  int64_t x = radius, y = 0;
  const double r0 = static_cast<double>(radius);
  bool y_first = false;
  int turn = 0;
  bool below_axis = false;  // in quadrant 4 (y < 0, x > 0): the next crossing ends a turn
  TurnStats stats;
  while (turn < turns) {
    const int64_t old_x = x, old_y = y;
    bool moved;
    if (scheme == Scheme::kSimultaneous) {
      moved = integrate(acc_x, -old_y, kpow, x);
      moved |= integrate(acc_y, old_x, kpow, y);
    } else if (!y_first) {
      moved = integrate(acc_x, -y, kpow, x);
      moved |= integrate(acc_y, x, kpow, y);
    } else {
      moved = integrate(acc_y, x, kpow, y);
      moved |= integrate(acc_x, -y, kpow, x);
    }
    if (scheme == Scheme::kAlternating) y_first = !y_first;
    ++stats.iterations;
    if (moved) {
      const double e = std::fabs(std::hypot(static_cast<double>(x), static_cast<double>(y)) - r0);
      if (e > stats.max_radial_error) stats.max_radial_error = e;
    }
    if (y < 0 && x > 0) below_axis = true;
    if (below_axis && y >= 0 && x > 0) {
      stats.end_x = x;
      stats.end_y = y;
      per_turn[turn++] = stats;
      stats = TurnStats{};
      below_axis = false;
    }
  }
}

}  // namespace ncinterp::circle_study
