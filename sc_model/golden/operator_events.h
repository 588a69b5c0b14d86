// The operator's actions during a run (`--events`, docs/motion-control.md): feed hold, cycle
// start, E-stop and the limit switches as the interpolator's hold_i, start_i, estop_i,
// limit_x_i and limit_y_i, each a one-clock press at its time (a stop latches: one clock
// stops the machine as a held button does); the feed and rapid overrides and the optional
// stop switch as the levels of feed_override_i, rapid_override_i and optional_stop_i from
// their time on.
// Idea: a run's inputs are the tape reader's frames (FrameSource) and these presses; both
// are plain data on the clock, so the golden model, the RTL in lock step, `check` and
// `play` see the very same clocks.
#pragma once
#include <algorithm>
#include <cstdint>
#include <string>
#include <vector>

#include "interp_ports.h"

namespace ncinterp {

struct OperatorEvent {
  enum Kind { kHold, kStart, kEStop, kLimitX, kLimitY, kFeedOverride, kRapidOverride, kOptionalStop };
  uint64_t cycle;  // the clock (1 = the first after reset) at which the button is down
  Kind kind;
  uint16_t value = 0;  // an override's P, in units of 1 / kOverrideOne; the switch's 1 (on), 0
};

// "hold@0.8s,resume@1.2s,override=50@1.5s,estop@2s": hold, resume (= start), start,
// override=P (P percent, 0 to 200, rounded to the nearest 1/128), rapid-override=P (25, 50
// or 100), estop, limit-x, limit-y and optional-stop=on or =off (the switch) at T seconds of
// machine time, in clocks of clock_hz;
// sorted by time. Anything else is refused naming the item and the names. Throws
// std::invalid_argument.
std::vector<OperatorEvent> parse_events(const std::string& list, double clock_hz);

// Orders events by clock, presses of one clock in their given order (parse_events() does).
void sort_by_clock(std::vector<OperatorEvent>& events);

// The list as --events reads it ("hold@0.5s,start@0.6s"): parse_events() gives `events`
// back at clock_hz.
std::string events_text(const std::vector<OperatorEvent>& events, double clock_hz);

// The press of `e` in the inputs of its clock (an override: the level it sets).
inline void press(InterpInputs& in, const OperatorEvent& e) {
  switch (e.kind) {
    case OperatorEvent::kHold: in.hold = true; break;
    case OperatorEvent::kStart: in.start = true; break;
    case OperatorEvent::kEStop: in.estop = true; break;
    case OperatorEvent::kLimitX: in.limit_x = true; break;
    case OperatorEvent::kLimitY: in.limit_y = true; break;
    case OperatorEvent::kFeedOverride: in.feed_override = e.value; break;
    case OperatorEvent::kRapidOverride: in.rapid_override = e.value; break;
    case OperatorEvent::kOptionalStop: in.optional_stop = e.value != 0; break;
  }
}

// The overrides of `events` (they need the ramp: an override changes the rate at the limit).
bool has_override(const std::vector<OperatorEvent>& events);
// An override's P in percent (its value in units of 1 / kOverrideOne).
inline double override_percent(uint16_t value) { return 100.0 * value / kOverrideOne; }

// The clock of the last event (0: none): a run's cycle limit adds it, as a hold or a pause
// lasts until a press.
inline uint64_t last_event_cycle(const std::vector<OperatorEvent>& events) {
  uint64_t last = 0;
  for (const OperatorEvent& e : events) last = std::max(last, e.cycle);
  return last;
}

// The first stop (E-stop or a limit) of `events`, or nullptr.
const OperatorEvent* first_stop(const std::vector<OperatorEvent>& events);
// The error a stop raises (kEStop: kEmergencyStop, kLimitX, kLimitY); kNone for the others.
TapeError stop_error(OperatorEvent::Kind kind);

}  // namespace ncinterp
