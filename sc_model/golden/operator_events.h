// The operator's actions during a run (`--events`, docs/motion-control.md): feed hold, cycle
// start, E-stop and the limit switches as the interpolator's hold_i, start_i, estop_i,
// limit_x_i and limit_y_i, each a one-clock press at its time (a stop latches: one clock
// stops the machine as a held button does).
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
  enum Kind { kHold, kStart, kEStop, kLimitX, kLimitY };
  uint64_t cycle;  // the clock (1 = the first after reset) at which the button is down
  Kind kind;
};

// "hold@0.8s,resume@1.2s,estop@2s": hold, resume (= start), start, estop, limit-x and limit-y
// at T seconds of machine time, in clocks of clock_hz; sorted by time. override=P and
// rapid-override=P are refused as not built yet; anything else is refused naming the item
// and the names. Throws std::invalid_argument.
std::vector<OperatorEvent> parse_events(const std::string& list, double clock_hz);

// Orders events by clock, presses of one clock in their given order (parse_events() does).
void sort_by_clock(std::vector<OperatorEvent>& events);

// The list as --events reads it ("hold@0.5s,start@0.6s"): parse_events() gives `events`
// back at clock_hz.
std::string events_text(const std::vector<OperatorEvent>& events, double clock_hz);

// The press of `kind` in the inputs of its clock.
inline void press(InterpInputs& in, OperatorEvent::Kind kind) {
  switch (kind) {
    case OperatorEvent::kHold: in.hold = true; break;
    case OperatorEvent::kStart: in.start = true; break;
    case OperatorEvent::kEStop: in.estop = true; break;
    case OperatorEvent::kLimitX: in.limit_x = true; break;
    case OperatorEvent::kLimitY: in.limit_y = true; break;
  }
}

// The first stop (E-stop or a limit) of `events`, or nullptr.
const OperatorEvent* first_stop(const std::vector<OperatorEvent>& events);
// The error a stop raises (kEStop: kEmergencyStop, kLimitX, kLimitY); kNone for the others.
TapeError stop_error(OperatorEvent::Kind kind);

}  // namespace ncinterp
