// Golden twin of rtl/board/uart_rx.sv: the 8N1 UART receiver, clock by clock.
// Idea: the same registers as the RTL (synchroniser, state, bit counter, shift register,
// valid / frame-error pulses) updated by the same rules at each rising edge, so
// tests/sc_model/board/test_board_lockstep.cpp can compare the two every clock; the board
// simulation's host side uses it to decode the board's TX line.
#pragma once
#include <cstdint>

namespace ncinterp::board {

class UartRxModel {
 public:
  void reset() { *this = UartRxModel(); }

  // One rising edge with input rx and bit_cycles clocks per bit (>= 4).
  void tick(bool rx, uint16_t bit_cycles) {
    State state = state_;
    uint16_t count = count_;
    uint8_t bit = bit_, shift = shift_;
    bool valid = false, ferr = false;
    switch (state_) {
      case State::kIdle:
        if (!sync_) {
          state = State::kStart;
          count = static_cast<uint16_t>((bit_cycles >> 1) - 1);
        }
        break;
      case State::kStart:
        if (count_ != 0) {
          count = count_ - 1;
        } else if (sync_) {
          state = State::kIdle;
        } else {
          state = State::kData;
          count = static_cast<uint16_t>(bit_cycles - 1);
          bit = 0;
        }
        break;
      case State::kData:
        if (count_ != 0) {
          count = count_ - 1;
        } else {
          shift = static_cast<uint8_t>((sync_ ? 0x80 : 0) | (shift_ >> 1));
          count = static_cast<uint16_t>(bit_cycles - 1);
          bit = (bit_ + 1) & 7;
          if (bit_ == 7) state = State::kStop;
        }
        break;
      case State::kStop:
        if (count_ != 0) {
          count = count_ - 1;
        } else if (sync_) {
          valid = true;
          state = State::kIdle;
        } else {
          ferr = true;
          state = State::kWaitHigh;
        }
        break;
      case State::kWaitHigh:
        if (sync_) state = State::kIdle;
        break;
    }
    sync_ = meta_;
    meta_ = rx;
    state_ = state;
    count_ = count;
    bit_ = bit;
    shift_ = shift;
    valid_ = valid;
    ferr_ = ferr;
  }

  uint8_t data() const { return shift_; }
  bool valid() const { return valid_; }
  bool frame_error() const { return ferr_; }

 private:
  enum class State { kIdle, kStart, kData, kStop, kWaitHigh };
  bool meta_ = true, sync_ = true;
  State state_ = State::kIdle;
  uint16_t count_ = 0;
  uint8_t bit_ = 0, shift_ = 0;
  bool valid_ = false, ferr_ = false;
};

}  // namespace ncinterp::board
