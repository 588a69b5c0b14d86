// The time base of every VCD the project writes (docs/waves.md): 1 ps units, a clock period
// of 1/clock_hz rounded to whole ps (at least 2, so half a period is a whole ps), the reset
// edge (cycle 0) at one period, edge c at (c + 1) periods, the clock low half a period
// before each edge. The cosim's RTL window (rtl_vcd.cpp) and the system model (its SystemC
// time and the RTL engine's dumps) all use these, so their files line up in GTKWave.
#pragma once
#include <algorithm>
#include <cmath>
#include <cstdint>

namespace ncinterp {

inline uint64_t vcd_period_ps(double clock_hz) {
  return std::max<uint64_t>(2, static_cast<uint64_t>(std::llround(1e12 / clock_hz)));
}

// Time of edge `cycle` (phase 1) or of the clock-low half before it (phase 0).
inline uint64_t vcd_edge_ps(uint64_t cycle, int phase, uint64_t period_ps) {
  return (cycle + 1) * period_ps - (phase == 0 ? period_ps / 2 : 0);
}

}  // namespace ncinterp
