// Golden twin of rtl/board/host_link.sv: which received bytes are tape frames and which are
// realtime commands (a byte of board_link.def's list, sent twice back to back), and the
// ACKs of the tape bytes taken out of the FIFO (character counting).
// Idea: the RTL's registers (the held first byte of a pair as its command bit, the command
// and lone-byte pulses, the bytes taken since the last ACK, the ACKs pending) with the same
// update rules, compared every clock by tests/sc_model/board/test_board_lockstep.cpp.
#pragma once
#include <cstdint>

#include "status_text.h"

namespace ncinterp::board {

// A byte's realtime command as its bit (interp_pkg::realtime_command()); 0: none.
inline uint32_t realtime_command_bit(uint8_t byte) {
  for (int i = 0; i < kRealtimeCommandCount; ++i)
    if (kRealtimeCommands[i].byte == byte) return 1u << i;
  return 0;
}

class HostLinkModel {
 public:
  // The byte at this clock is a tape frame (with valid).
  bool frame(uint8_t rx) const { return held_ == 0 && realtime_command_bit(rx) == 0; }
  uint32_t command() const { return command_; }
  bool lone() const { return lone_; }
  bool ack() const { return acks_ != 0; }

  // One rising edge.
  void tick(uint8_t rx, bool rx_valid, bool taken, bool ack_sent) {
    command_ = 0;
    lone_ = false;
    if (rx_valid) {
      const uint32_t c = realtime_command_bit(rx);
      if (held_ != 0) {
        command_ = held_ == c ? held_ : 0;
        lone_ = held_ != c;
        held_ = 0;
      } else {
        held_ = c;
      }
    }
    const bool chunk_done = taken && taken_ == kLinkAckBytes - 1;
    if (taken) taken_ = (taken_ + 1) % kLinkAckBytes;
    acks_ = acks_ + (chunk_done ? 1 : 0) - (ack_sent ? 1 : 0);
  }

 private:
  uint32_t held_ = 0, command_ = 0;
  bool lone_ = false;
  unsigned taken_ = 0, acks_ = 0;
};

}  // namespace ncinterp::board
