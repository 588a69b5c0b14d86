// Golden twin of rtl/board/step_stretcher.sv: the step pulse stretcher of one axis.
// Idea: the RTL's phases (IDLE, SETUP, HIGH, LOW), clock counter and one-deep pulse buffer
// with the same update rules, compared every clock by
// tests/sc_model/board/test_board_lockstep.cpp.
#pragma once
#include <cstdint>

namespace ncinterp::board {

struct StretcherTiming {
  uint16_t setup_cycles = 1, pulse_cycles = 1, low_cycles = 1;  // each >= 1
};

class StepStretcherModel {
 public:
  void reset() { *this = StepStretcherModel(); }

  bool step() const { return step_; }
  bool dir() const { return dir_; }
  bool overrun() const { return overrun_; }

  // One rising edge with the interpolator's step and dir.
  void tick(bool step_in, bool dir_in, const StretcherTiming& t) {
    // count_: the clocks of the phase so far (1 at its first); the phase ends where it
    // equals the phase's length.
    const uint16_t length = phase_ == Phase::kSetup ? t.setup_cycles
                            : phase_ == Phase::kHigh ? t.pulse_cycles
                                                     : t.low_cycles;
    const bool phase_end = count_ == length;
    Phase phase = phase_;
    uint16_t count = static_cast<uint16_t>(count_ + 1);
    bool step = step_, dir = dir_;
    bool take = false, took_pend = false, take_dir = dir_in;
    switch (phase_) {
      case Phase::kIdle:
        if (pend_) {
          take = took_pend = true;
          take_dir = pend_dir_;
        } else if (step_in) {
          take = true;
        }
        if (take) {
          if (take_dir != dir_) {
            dir = take_dir;
            phase = Phase::kSetup;
          } else {
            step = true;
            phase = Phase::kHigh;
          }
        }
        break;
      case Phase::kSetup:
        if (phase_end) {
          step = true;
          phase = Phase::kHigh;
        }
        break;
      case Phase::kHigh:
        if (phase_end) {
          step = false;
          phase = Phase::kLow;
        }
        break;
      case Phase::kLow:
        if (phase_end) phase = Phase::kIdle;
        break;
    }
    if (phase != phase_) count = 1;  // a new phase starts at its first clock
    bool pend = pend_ && !took_pend, pend_dir = pend_dir_, overrun = false;
    if (step_in && !(take && !took_pend)) {
      if (pend) {
        overrun = true;
      } else {
        pend = true;
        pend_dir = dir_in;
      }
    }
    phase_ = phase;
    count_ = count;
    step_ = step;
    dir_ = dir;
    pend_ = pend;
    pend_dir_ = pend_dir;
    overrun_ = overrun;
  }

 private:
  enum class Phase { kIdle, kSetup, kHigh, kLow };
  Phase phase_ = Phase::kIdle;
  uint16_t count_ = 0;
  bool pend_ = false, pend_dir_ = false;
  bool step_ = false, dir_ = false, overrun_ = false;
};

}  // namespace ncinterp::board
