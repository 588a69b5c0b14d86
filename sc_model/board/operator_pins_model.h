// Golden twin of rtl/board/operator_pins.sv: the board's operator pins as interp_top's
// inputs.
// Idea: the RTL's two synchronizer stages, its shared prescaler, the buttons' last sample,
// debounced level and press (a pin's or the host's), and the override counts, with the
// same update rules, compared every clock by tests/sc_model/board/test_board_lockstep.cpp.
#pragma once
#include <array>
#include <cstdint>

#include "feed_override.h"

namespace ncinterp::board {

// The pins in the RTL's synchronizer order, the buttons first (active high: pressed,
// tripped, on).
enum OperatorPin {
  kPinHold, kPinStart, kPinFeedUp, kPinFeedDown, kPinFeedReset, kPinRapid,
  kPinEStop, kPinLimitX, kPinLimitY, kPinOptionalStop, kOperatorPins
};
constexpr int kOperatorButtons = kPinRapid + 1;

class OperatorPinsModel {
 public:
  explicit OperatorPinsModel(unsigned debounce_width) : mask_((uint64_t{1} << debounce_width) - 1) {}

  bool hold() const { return press_[kPinHold]; }
  bool start() const { return press_[kPinStart]; }
  // The RTL registers override_of_tens() of the count: the same value, one clock later
  // than its button's press, as the count.
  uint16_t feed_override() const { return override_units(10.0 * tens_); }
  uint16_t rapid_override() const { return static_cast<uint16_t>(kOverrideOne >> rapid_); }
  bool estop() const { return sync_[kPinEStop] || remote_estop_; }
  bool limit_x() const { return sync_[kPinLimitX]; }
  bool limit_y() const { return sync_[kPinLimitY]; }
  bool optional_stop() const { return sync_[kPinOptionalStop]; }

  // One rising edge with the pins' levels and the host's commands (remote: a bit each, the
  // buttons' in pin order, then the E-stop; HostLinkModel::command()).
  void tick(const std::array<bool, kOperatorPins>& pins, uint32_t remote = 0) {
    const bool tick = prescale_ == mask_;
    prescale_ = (prescale_ + 1) & mask_;
    std::array<bool, kOperatorButtons> press{};
    for (int b = 0; b < kOperatorButtons; ++b)
      press[b] = (tick && sync_[b] && sample_[b] && !down_[b]) || (remote >> b & 1);
    remote_estop_ = remote >> kOperatorButtons & 1;
    if (press[kPinFeedReset]) tens_ = kOverrideTensAtOne;
    else if (press[kPinFeedUp] && tens_ != kOverrideTens) ++tens_;
    else if (press[kPinFeedDown] && tens_ != 0) --tens_;
    if (press[kPinRapid]) rapid_ = rapid_ == 2 ? 0 : rapid_ + 1;
    press_ = press;
    if (tick) {
      for (int b = 0; b < kOperatorButtons; ++b) {
        if (sync_[b] == sample_[b]) down_[b] = sync_[b];
        sample_[b] = sync_[b];
      }
    }
    sync_ = meta_;
    meta_ = pins;
  }

 private:
  uint64_t mask_, prescale_ = 0;
  std::array<bool, kOperatorPins> meta_{}, sync_{};
  std::array<bool, kOperatorButtons> sample_{}, down_{}, press_{};
  bool remote_estop_ = false;
  unsigned tens_ = kOverrideTensAtOne, rapid_ = 0;
};

}  // namespace ncinterp::board
