// Which part of a run goes into the VCD: --vcd-from / --vcd-to as clock cycles ("1000") or
// block boundaries ("N12": the start or the end of the first block N12).
// Idea: a whole part at full clock makes a huge VCD, so the tracer is opened late and
// closed early. Block bounds are turned into cycles before the run by a quick pass of the
// golden cycle model (plain C++, no SystemC): the RTL has the same cycle timing (the
// cosim checks it every clock), so the window is exact for both engines, and the VCD can
// start half a clock before the block's load edge instead of after it.
#pragma once
#include <cstdint>
#include <limits>
#include <optional>
#include <string>
#include <vector>

#include "interp_ports.h"

namespace ncinterp::system {

struct VcdBound {
  enum class Kind { kCycle, kBlock } kind = Kind::kCycle;
  uint64_t value = 0;  // cycle, or block N
};

// "1000" -> cycle 1000, "N12" -> block 12. Throws std::invalid_argument otherwise.
VcdBound parse_vcd_bound(const std::string& text);

// Cycles are edges after reset (cycle 0 = the reset edge, cycle 1 = the first tick). The VCD
// covers edges from..to: it opens half a clock before edge `from` and closes half a clock
// after edge `to`. A block's start is its load edge, its end the edge where the next block
// loads or busy falls (docs/interpolator.md 5.4).
struct CycleWindow {
  uint64_t from = 0;
  uint64_t to = std::numeric_limits<uint64_t>::max();
};

// Throws std::runtime_error when a block bound names a block that never plays, or when
// from > to.
CycleWindow resolve_vcd_window(const std::optional<VcdBound>& from,
                               const std::optional<VcdBound>& to,
                               const std::vector<uint8_t>& frames, const InterpConfig& cfg,
                               uint64_t cycles_per_frame, uint64_t max_cycles);

}  // namespace ncinterp::system
