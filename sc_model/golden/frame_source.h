// Tape reader model: delivers a tape's frames to the interpolator over valid/ready at a
// reader rate, one clock at a time, and with them the operator's presses (feed hold, cycle
// start, E-stop, limits: operator_events.h) at their clocks and the overrides' levels.
// Plain C++ so the lock-step cosim and the SystemC tape-reader module use the very same
// timing.
// Idea: a start/stop reader needs `cycles_per_frame` clocks to bring the next character
// under the read head; the character stays valid until the decoder takes it (valid and
// ready at one rising edge). tape_end rises once the last frame has been taken.
#pragma once
#include <algorithm>
#include <cstdint>
#include <utility>
#include <vector>

#include "interp_ports.h"
#include "operator_events.h"

namespace ncinterp {

class FrameSource {
 public:
  FrameSource(std::vector<uint8_t> frames, uint64_t cycles_per_frame,
              std::vector<OperatorEvent> events = {})
      : frames_(std::move(frames)),
        events_(std::move(events)),
        cycles_per_frame_(cycles_per_frame ? cycles_per_frame : 1),
        countdown_(cycles_per_frame_ - 1) {
    for (size_t k = 0; k < events_.size(); ++k)
      if (events_[k].kind == OperatorEvent::kStart) starts_end_ = k + 1;
  }

  // Cycles per frame for a reader of `chars_per_second` at `clock_hz` (at least 1).
  static uint64_t cycles_per_frame_for(double clock_hz, double chars_per_second) {
    const double cycles = clock_hz / chars_per_second;
    return cycles < 1.0 ? 1 : static_cast<uint64_t>(cycles + 0.5);
  }

  // The inputs the interpolator sees during the current clock.
  InterpInputs inputs() const {
    InterpInputs in;
    in.frame_valid = next_ < frames_.size() && countdown_ == 0;
    in.frame = in.frame_valid ? frames_[next_] : 0;
    in.tape_end = next_ >= frames_.size();
    in.feed_override = feed_override_;
    in.rapid_override = rapid_override_;
    in.optional_stop = optional_stop_;
    for (size_t k = next_event_; k < events_.size() && events_[k].cycle == clocks_ + 1; ++k)
      press(in, events_[k]);
    return in;
  }

  // One rising edge; `ready` is the interpolator's frame_ready before that edge.
  void clock(bool ready) {
    ++clocks_;
    for (; next_event_ < events_.size() && events_[next_event_].cycle <= clocks_; ++next_event_) {
      const OperatorEvent& e = events_[next_event_];
      if (e.kind == OperatorEvent::kFeedOverride) feed_override_ = e.value;
      if (e.kind == OperatorEvent::kRapidOverride) rapid_override_ = e.value;
      if (e.kind == OperatorEvent::kOptionalStop) optional_stop_ = e.value != 0;
    }
    if (next_ >= frames_.size()) return;
    if (countdown_ > 0) {
      --countdown_;
    } else if (ready) {
      ++next_;
      countdown_ = cycles_per_frame_ - 1;
    }
  }

  // Event jumping (GoldenInterp::quiet_ticks): the clocks from now during which inputs()
  // stays as it is while no frame is taken: the wait for the next frame, or (0 clocks
  // left) a frame waiting under the head; skip(n), n <= that, is n such clocks.
  // An operator's press bounds it too: the clocks before it.
  uint64_t steady_clocks() const {
    uint64_t n = next_ < frames_.size() && countdown_ > 0 ? countdown_ : UINT64_MAX;
    if (next_event_ < events_.size()) n = std::min(n, events_[next_event_].cycle - (clocks_ + 1));
    return n;
  }
  void skip(uint64_t n) {
    clocks_ += n;
    if (next_ < frames_.size() && countdown_ > 0) countdown_ -= n;
  }

  uint64_t frames_taken() const { return next_; }
  const std::vector<uint8_t>& frames() const { return frames_; }

  // The run is over after outputs `o`: the program ended or stopped on an error, or it is
  // paused (M00, M01) and no cycle start press is still to come.
  bool run_over(const InterpOutputs& o) const {
    return o.done || o.error || (o.paused && next_event_ >= starts_end_);
  }

 private:
  std::vector<uint8_t> frames_;
  std::vector<OperatorEvent> events_;  // sorted by cycle
  size_t next_event_ = 0;              // the first not yet past
  size_t starts_end_ = 0;              // after the last cycle start press (0: none)
  uint16_t feed_override_ = kOverrideOne, rapid_override_ = kOverrideOne;  // the levels set
  bool optional_stop_ = false;  // the optional stop switch
  uint64_t clocks_ = 0;                // edges so far: the current clock is clocks_ + 1
  uint64_t cycles_per_frame_;
  uint64_t next_ = 0;      // index of the frame under the read head
  uint64_t countdown_;     // clocks until that frame is readable
};

}  // namespace ncinterp
