// Lock step of the board RTL's modules against their golden twins, every clock:
// uart_rx (rtl/board/uart_rx.sv) vs UartRxModel, uart_tx (rtl/board/uart_tx.sv) vs
// UartTxModel, step_stretcher (rtl/board/step_stretcher.sv) vs StepStretcherModel,
// operator_pins (rtl/board/operator_pins.sv) vs OperatorPinsModel, host_link
// (rtl/board/host_link.sv) vs HostLinkModel, under random stimulus (bytes, gaps, bit times,
// framing errors, glitches; step trains with direction changes faster and slower than the
// driver timing; buttons pressed with bouncing contacts and the host's commands; tape
// bytes, realtime pairs and lone realtime bytes, a FIFO drained at random).
// Besides agreeing, the twins must do their job: bytes arrive as sent, pulses keep their
// width and set-up time, a bouncing press is one press.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <deque>
#include <random>

#include "Vhost_link.h"
#include "Voperator_pins.h"
#include "Vstep_stretcher.h"
#include "Vuart_rx.h"
#include "Vuart_tx.h"
#include "host_link_model.h"
#include "operator_pins_model.h"
#include "step_stretcher_model.h"
#include "uart_rx_model.h"
#include "uart_tx_model.h"
#include "verilated.h"
#include "verilated_clock.h"

namespace ncinterp::board {
namespace {

using test::clock_edge;
using test::reset;

TEST(BoardLockstep, UartRxMatchesItsTwin) {
  std::mt19937_64 rng(14);
  for (int round = 0; round < 12; ++round) {
    const uint16_t bit = static_cast<uint16_t>(4 + rng() % 40);
    Vuart_rx rtl;
    reset(rtl);
    UartRxModel twin;
    UartTxModel line;  // the sender
    rtl.bit_cycles_i = bit;
    std::deque<uint8_t> sent;
    std::vector<uint8_t> got;
    unsigned errors = 0, gap = 0;
    for (uint64_t c = 0; c < 40000; ++c) {
      // A byte now and then, sometimes back to back; a framing error (stop bit forced low)
      // or a short glitch on the idle line now and then.
      const bool offer = line.ready() && gap == 0;
      const uint8_t byte = static_cast<uint8_t>(rng());
      bool rx = line.tx();
      const unsigned r = static_cast<unsigned>(rng() % 4000);
      if (r == 0 && !line.ready()) rx = false;       // corrupts a bit (may break the frame)
      if (r == 1 && line.ready()) rx = false;        // a one-clock glitch on the idle line
      rtl.rx_i = rx;
      clock_edge(rtl);
      twin.tick(rx, bit);
      line.tick(byte, offer, bit);
      if (offer) {
        sent.push_back(byte);
        gap = rng() % 3 == 0 ? 0 : static_cast<unsigned>(rng() % (30 * bit));
      } else if (gap) {
        --gap;
      }
      ASSERT_EQ(rtl.valid_o, twin.valid()) << "clock " << c << " bit " << bit;
      ASSERT_EQ(rtl.frame_error_o, twin.frame_error()) << "clock " << c;
      ASSERT_EQ(rtl.data_o, twin.data()) << "clock " << c;
      if (twin.valid()) got.push_back(twin.data());
      errors += twin.frame_error();
    }
    // Without disturbances every byte arrives as sent; with them most still do.
    EXPECT_GT(got.size() + errors, sent.size() / 2);
    size_t match = 0;
    for (size_t i = 0; i < std::min(got.size(), sent.size()); ++i) match += got[i] == sent[i];
    EXPECT_GT(match, 0u);
  }
}

TEST(BoardLockstep, UartRxReceivesEveryByteOfACleanLine) {
  for (uint16_t bit : {4, 5, 9, 104}) {
    Vuart_rx rtl;
    reset(rtl);
    rtl.bit_cycles_i = bit;
    UartTxModel line;
    std::vector<uint8_t> got;
    unsigned next = 0;
    for (uint64_t c = 0; c < 300ull * 10 * bit && got.size() < 256; ++c) {
      const bool offer = line.ready() && next < 256;
      rtl.rx_i = line.tx();
      clock_edge(rtl);
      line.tick(static_cast<uint8_t>(next), offer, bit);
      next += offer;
      if (rtl.valid_o) got.push_back(rtl.data_o);
      ASSERT_FALSE(rtl.frame_error_o) << "bit " << bit << " clock " << c;
    }
    ASSERT_EQ(got.size(), 256u) << "bit " << bit;
    for (unsigned i = 0; i < 256; ++i) ASSERT_EQ(got[i], i) << "bit " << bit;
  }
}

TEST(BoardLockstep, UartTxMatchesItsTwin) {
  std::mt19937_64 rng(15);
  for (int round = 0; round < 8; ++round) {
    const uint16_t bit = static_cast<uint16_t>(4 + rng() % 30);
    Vuart_tx rtl;
    reset(rtl);
    rtl.bit_cycles_i = bit;
    UartTxModel twin;
    UartRxModel listener;
    std::vector<uint8_t> sent, got;
    for (uint64_t c = 0; c < 30000; ++c) {
      ASSERT_EQ(rtl.ready_o, twin.ready()) << "clock " << c;
      ASSERT_EQ(rtl.tx_o, twin.tx()) << "clock " << c;
      const uint8_t byte = static_cast<uint8_t>(rng());
      const bool valid = rng() % 3 != 0;
      if (valid && twin.ready()) sent.push_back(byte);
      rtl.data_i = byte;
      rtl.valid_i = valid;
      const bool line = twin.tx();
      clock_edge(rtl);
      twin.tick(byte, valid, bit);
      listener.tick(line, bit);
      if (listener.valid()) got.push_back(listener.data());
      ASSERT_FALSE(listener.frame_error());
    }
    ASSERT_GE(sent.size(), got.size());
    ASSERT_GE(got.size() + 1, sent.size());  // the last one may still be on the line
    for (size_t i = 0; i < got.size(); ++i) ASSERT_EQ(got[i], sent[i]);
  }
}

TEST(BoardLockstep, StepStretcherMatchesItsTwin) {
  std::mt19937_64 rng(16);
  for (int round = 0; round < 24; ++round) {
    StretcherTiming t;
    t.setup_cycles = static_cast<uint16_t>(1 + rng() % 12);
    t.pulse_cycles = static_cast<uint16_t>(1 + rng() % 24);
    t.low_cycles = static_cast<uint16_t>(1 + rng() % 24);
    // Mean step spacing from much faster than the driver timing (overruns) to slower.
    const unsigned spacing = 1 + static_cast<unsigned>(rng() % (4 * (t.setup_cycles + t.pulse_cycles + t.low_cycles)));
    Vstep_stretcher rtl;
    reset(rtl);
    rtl.setup_cycles_i = t.setup_cycles;
    rtl.pulse_cycles_i = t.pulse_cycles;
    rtl.low_cycles_i = t.low_cycles;
    StepStretcherModel twin;
    bool dir = false, prev_step = false;
    uint64_t in = 0, out = 0, overruns = 0, dir_change = 0, high_since = 0;
    for (uint64_t c = 1; c < 20000; ++c) {
      if (rng() % 16 == 0) dir = !dir;
      const bool step = rng() % spacing == 0;
      in += step;
      rtl.step_i = step;
      rtl.dir_i = dir;
      const bool dir_before = twin.dir();
      clock_edge(rtl);
      twin.tick(step, dir, t);
      ASSERT_EQ(rtl.step_o, twin.step()) << "clock " << c;
      ASSERT_EQ(rtl.dir_o, twin.dir()) << "clock " << c;
      ASSERT_EQ(rtl.overrun_o, twin.overrun()) << "clock " << c;
      overruns += twin.overrun();
      if (twin.dir() != dir_before) {
        EXPECT_FALSE(twin.step()) << "dir changed during a pulse, clock " << c;
        dir_change = c;
      }
      if (twin.step() && !prev_step) {
        ++out;
        high_since = c;
        if (dir_change) EXPECT_GE(c - dir_change, t.setup_cycles) << "dir set-up, clock " << c;
      }
      if (!twin.step() && prev_step) EXPECT_EQ(c - high_since, t.pulse_cycles) << "pulse width, clock " << c;
      prev_step = twin.step();
    }
    // Every pulse comes out unless it was reported lost (two may still be on their way).
    EXPECT_LE(out + overruns, in);
    EXPECT_GE(out + overruns + 2, in) << "round " << round;
  }
}

// The pins at a 16-clock sample period (DebounceWidth 4): each round presses the buttons
// and trips the switches at random, each change with a burst of bounces shorter than a
// sample period. Every press of a button (down for two sample periods and more) is exactly
// one press, whatever its bounces: one clock of hold_o or start_o, one step of an
// override; the overrides stay on their steps; the switches follow their pins through two
// flip-flops.
TEST(BoardLockstep, OperatorPinsMatchTheirTwinAndABouncingPressIsOnePress) {
  constexpr unsigned kWidth = 4, kPeriod = 1u << kWidth;
  std::mt19937_64 rng(17);
  Voperator_pins rtl;
  reset(rtl);
  OperatorPinsModel twin(kWidth);
  std::array<bool, kOperatorPins> pins{}, settled{}, before{};
  std::array<uint64_t, kOperatorButtons> pressed{};
  std::array<uint64_t, 2> presses{};
  std::array<uint64_t, kOperatorPins> settle_at{};
  uint64_t override_changes = 0;
  std::array<uint64_t, kOperatorButtons> remote_presses{};
  uint16_t last_override = twin.feed_override();
  for (uint64_t c = 1; c < 200000; ++c) {
    for (int p = 0; p < kOperatorPins; ++p) {
      // A change of a pin's settled level every ~50 sample periods, each level held three
      // periods at least; the contact bounces for up to half a period after it.
      if (c >= settle_at[p] + 3 * kPeriod && rng() % (50 * kPeriod) == 0) {
        settled[p] = !settled[p];
        settle_at[p] = c + rng() % (kPeriod / 2);
        if (p < kOperatorButtons && settled[p]) ++pressed[p];
      }
      pins[p] = c < settle_at[p] ? rng() % 2 == 0 : settled[p];
    }
    rtl.hold_i = pins[kPinHold];
    rtl.start_i = pins[kPinStart];
    rtl.feed_up_i = pins[kPinFeedUp];
    rtl.feed_down_i = pins[kPinFeedDown];
    rtl.feed_reset_i = pins[kPinFeedReset];
    rtl.rapid_cycle_i = pins[kPinRapid];
    rtl.estop_i = pins[kPinEStop];
    rtl.limit_x_i = pins[kPinLimitX];
    rtl.limit_y_i = pins[kPinLimitY];
    rtl.optional_stop_i = pins[kPinOptionalStop];
    // Now and then one clock of a host's command (HostLinkModel's pulses are a byte apart);
    // not the E-stop, whose pin the test below follows.
    const uint32_t remote = rng() % 500 == 0 ? 1u << (rng() % kOperatorButtons) : 0;
    for (int b = 0; b < kOperatorButtons; ++b) remote_presses[b] += remote >> b & 1;
    rtl.remote_i = remote;
    clock_edge(rtl);
    twin.tick(pins, remote);
    ASSERT_EQ(rtl.hold_o, twin.hold()) << "clock " << c;
    ASSERT_EQ(rtl.start_o, twin.start()) << "clock " << c;
    ASSERT_EQ(rtl.feed_override_o, twin.feed_override()) << "clock " << c;
    ASSERT_EQ(rtl.rapid_override_o, twin.rapid_override()) << "clock " << c;
    ASSERT_EQ(rtl.estop_o, twin.estop()) << "clock " << c;
    ASSERT_EQ(rtl.limit_x_o, twin.limit_x()) << "clock " << c;
    ASSERT_EQ(rtl.limit_y_o, twin.limit_y()) << "clock " << c;
    ASSERT_EQ(rtl.optional_stop_o, twin.optional_stop()) << "clock " << c;
    presses[0] += twin.hold();
    presses[1] += twin.start();
    if (twin.feed_override() != last_override) ++override_changes;
    last_override = twin.feed_override();
    // The overrides on their steps: tens of percent, and 100, 50, 25 %.
    ASSERT_EQ(twin.feed_override(), override_units(std::round(twin.feed_override() * 10.0 / kOverrideOne) * 10))
        << "clock " << c;
    ASSERT_TRUE(twin.rapid_override() == 128 || twin.rapid_override() == 64 || twin.rapid_override() == 32);
    // The switches: the pin as the edge before took it (two flip-flops).
    ASSERT_EQ(twin.estop(), before[kPinEStop]) << "clock " << c;
    ASSERT_EQ(twin.limit_y(), before[kPinLimitY]) << "clock " << c;
    before = pins;
  }
  // Every settled press is one press, and so is every command of the host's; the last
  // press may still be in the debouncer. An override moves at most once per press of its
  // buttons.
  // (A host's press in the same clock as a pin's is one press: rare, and allowed for.)
  for (int b = 0; b < 2; ++b) {
    EXPECT_GT(pressed[b], 50u);
    EXPECT_GT(remote_presses[b], 10u);
    EXPECT_LE(presses[b], pressed[b] + remote_presses[b]) << "button " << b;
    EXPECT_GE(presses[b] + 2, pressed[b] + remote_presses[b]) << "button " << b;
  }
  EXPECT_GT(override_changes, 50u);
  EXPECT_LE(override_changes, pressed[kPinFeedUp] + pressed[kPinFeedDown] + pressed[kPinFeedReset] +
                                  remote_presses[kPinFeedUp] + remote_presses[kPinFeedDown] +
                                  remote_presses[kPinFeedReset]);
}

// host_link against its twin: a random byte stream of tape bytes (any byte that is no
// realtime command), realtime pairs and now and then a lone realtime byte, bytes a few
// clocks apart; a FIFO of the frames drained at random; each ACK sent a random while after
// it is asked for. Besides agreeing: the frames come out in order and complete, every pair
// is one command, every lone byte one error, and one ACK per LinkAckBytes bytes taken.
TEST(BoardLockstep, HostLinkMatchesItsTwinAndCountsWhatItTakes) {
  std::mt19937_64 rng(18);
  Vhost_link rtl;
  reset(rtl);
  HostLinkModel twin;
  std::deque<uint8_t> to_send, fifo;
  std::vector<uint8_t> frames_sent, frames_got;
  uint64_t pairs = 0, lones = 0, commands = 0, lone_errors = 0, taken = 0, acks = 0;
  unsigned gap = 0, ack_wait = 0;
  for (uint64_t c = 1; c < 400000; ++c) {
    if (to_send.empty()) {
      const unsigned r = static_cast<unsigned>(rng() % 100);
      const uint8_t rt = kRealtimeCommands[rng() % kRealtimeCommandCount].byte;
      if (r < 10) {
        to_send = {rt, rt};
        ++pairs;
      } else if (r < 11) {
        uint8_t next = static_cast<uint8_t>(rng());
        while (realtime_command_bit(next) != 0) next = static_cast<uint8_t>(rng());
        to_send = {rt, next};  // the byte after a lone one is lost with it
        ++lones;
      } else {
        uint8_t b = static_cast<uint8_t>(rng());
        while (realtime_command_bit(b) != 0) b = static_cast<uint8_t>(rng());
        to_send = {b};
        frames_sent.push_back(b);
      }
    }
    const bool valid = gap == 0 && fifo.size() < kLinkFifoBytes;
    const uint8_t rx = valid ? to_send.front() : static_cast<uint8_t>(rng());
    gap = valid ? static_cast<unsigned>(2 + rng() % 8) : gap - (gap > 0);
    const bool take = !fifo.empty() && rng() % 6 == 0;
    const bool ack_sent = twin.ack() && ack_wait == 0;
    ack_wait = ack_sent ? static_cast<unsigned>(rng() % 40) : ack_wait - (ack_wait > 0);
    rtl.rx_data_i = rx;
    rtl.rx_valid_i = valid;
    rtl.taken_i = take;
    rtl.ack_sent_i = ack_sent;
    rtl.eval();
    const bool frame = twin.frame(rx);
    ASSERT_EQ(bool(rtl.frame_o), frame) << "clock " << c;  // combinational: before the edge
    clock_edge(rtl);
    twin.tick(rx, valid, take, ack_sent);
    if (valid) {
      to_send.pop_front();
      if (frame) fifo.push_back(rx);
    }
    if (take) {
      frames_got.push_back(fifo.front());
      fifo.pop_front();
      ++taken;
    }
    acks += ack_sent;
    ASSERT_EQ(rtl.command_o, twin.command()) << "clock " << c;
    ASSERT_EQ(bool(rtl.lone_o), twin.lone()) << "clock " << c;
    ASSERT_EQ(bool(rtl.ack_o), twin.ack()) << "clock " << c;
    commands += twin.command() != 0;
    lone_errors += twin.lone();
  }
  EXPECT_GT(pairs, 1000u);
  EXPECT_GT(lones, 100u);
  EXPECT_EQ(commands + 1 >= pairs && commands <= pairs, true) << commands << " of " << pairs;
  EXPECT_EQ(lone_errors + 1 >= lones && lone_errors <= lones, true) << lone_errors << " of " << lones;
  frames_sent.resize(frames_got.size());
  EXPECT_EQ(frames_got, frames_sent);
  EXPECT_GT(taken, 10000u);
  EXPECT_LE(acks, taken / kLinkAckBytes);
  EXPECT_GE(acks + 1, taken / kLinkAckBytes);
}

}  // namespace
}  // namespace ncinterp::board
