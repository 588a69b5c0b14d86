// Golden twin of rtl/board/uart_tx.sv: the 8N1 UART transmitter, clock by clock.
// Idea: the RTL's three registers (bits left to send, shift register, bit clock counter)
// with the same update rules, compared every clock by
// tests/sc_model/board/test_board_lockstep.cpp; the board simulation's host side uses it
// to drive the board's RX line.
#pragma once
#include <cstdint>

namespace ncinterp::board {

class UartTxModel {
 public:
  void reset() { *this = UartTxModel(); }

  // Outputs before the edge (functions of the registers).
  bool ready() const { return left_ == 0; }
  bool tx() const { return left_ == 0 ? true : (shift_ & 1u) != 0; }

  // One rising edge: `valid` offers `data` (taken when ready()).
  void tick(uint8_t data, bool valid, uint16_t bit_cycles) {
    if (left_ == 0) {
      if (valid) {
        shift_ = static_cast<uint16_t>(0x200u | (static_cast<unsigned>(data) << 1));
        left_ = 10;
        count_ = static_cast<uint16_t>(bit_cycles - 1);
      }
    } else if (count_ != 0) {
      --count_;
    } else {
      shift_ = static_cast<uint16_t>(0x200u | (shift_ >> 1));
      --left_;
      count_ = static_cast<uint16_t>(bit_cycles - 1);
    }
  }

 private:
  uint16_t shift_ = 0x3ff;
  uint8_t left_ = 0;
  uint16_t count_ = 0;
};

}  // namespace ncinterp::board
