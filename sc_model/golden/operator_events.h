// The operator's actions during a run (`--events`, docs/motion-control.md): feed hold and
// cycle start as the interpolator's hold_i and start_i, each a one-clock press at its time.
// Idea: a run's inputs are the tape reader's frames (FrameSource) and these presses; both
// are plain data on the clock, so the golden model, the RTL in lock step, `check` and
// `play` see the very same clocks.
#pragma once
#include <cstdint>
#include <string>
#include <vector>

#include "interp_ports.h"

namespace ncinterp {

struct OperatorEvent {
  enum Kind { kHold, kStart };
  uint64_t cycle;  // the clock (1 = the first after reset) at which the button is down
  Kind kind;
};

// "hold@0.8s,resume@1.2s,start@2s": hold, resume (= start) and start at T seconds of machine
// time, in clocks of clock_hz; sorted by time. The other names of the list (override=P,
// rapid-override=P, estop, limit-x, limit-y) are refused as not built yet; anything else is
// refused naming the item and the names. Throws std::invalid_argument.
std::vector<OperatorEvent> parse_events(const std::string& list, double clock_hz);

}  // namespace ncinterp
