// Golden twin of rtl/board/operator_pins.sv: the board's operator pins as interp_top's
// inputs.
// Idea: the RTL's two synchronizer stages, its shared prescaler and the buttons' last
// sample, debounced level and press, with the same update rules, compared every clock by
// tests/sc_model/board/test_board_lockstep.cpp.
#pragma once
#include <array>
#include <cstdint>

namespace ncinterp::board {

// The pins in the RTL's synchronizer order (active high: pressed, tripped, on).
enum OperatorPin { kPinHold, kPinStart, kPinEStop, kPinLimitX, kPinLimitY, kPinOptionalStop, kOperatorPins };

class OperatorPinsModel {
 public:
  explicit OperatorPinsModel(unsigned debounce_width) : mask_((uint64_t{1} << debounce_width) - 1) {}

  bool hold() const { return press_[kPinHold]; }
  bool start() const { return press_[kPinStart]; }
  bool estop() const { return sync_[kPinEStop]; }
  bool limit_x() const { return sync_[kPinLimitX]; }
  bool limit_y() const { return sync_[kPinLimitY]; }
  bool optional_stop() const { return sync_[kPinOptionalStop]; }

  // One rising edge with the pins' levels.
  void tick(const std::array<bool, kOperatorPins>& pins) {
    const bool tick = prescale_ == mask_;
    prescale_ = (prescale_ + 1) & mask_;
    press_ = {};
    if (tick) {
      for (int b : {kPinHold, kPinStart}) {
        if (sync_[b] == sample_[b]) {
          press_[b] = sync_[b] && !down_[b];
          down_[b] = sync_[b];
        }
        sample_[b] = sync_[b];
      }
    }
    sync_ = meta_;
    meta_ = pins;
  }

 private:
  uint64_t mask_, prescale_ = 0;
  std::array<bool, kOperatorPins> meta_{}, sync_{};
  std::array<bool, 2> sample_{}, down_{}, press_{};
};

}  // namespace ncinterp::board
