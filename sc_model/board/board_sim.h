// The virtual board: the verilated board core (rtl/board/board_core.sv, UART included)
// clocked in simulated time and wired to a pseudo-terminal, so a serial program (`ncinterp
// send`) talks to it through a real tty.
// Idea: the sim plays the part of the board's USB-serial chip (an FT2232H). Its host-side
// UART transmitter (UartTxModel) sends the bytes the sender wrote into the pty on the
// board's RX pin at the simulated baud rate, one after another, and stops before a byte
// while the board holds CTS# high (RTS/CTS) or after the board sent XOFF until XON
// (XON/XOFF), as the FT2232H does in hardware with CRTSCTS or IXON set; with character
// counting it holds nothing back (the sender counts the board's ACKs). Its host-side
// receiver (UartRxModel) decodes the board's TX pin and writes every byte into the pty. A
// pty has no baud rate and no CTS line, so the wire's pacing and the flow control live
// here; the kernel's pty buffer is the USB chip's buffer and blocks a fast sender.
// Simulated time runs on while the sender is slow (an idle line), so timing figures in the
// report depend on the host; pulses and positions do not. The run ends when the board has
// sent its "D" (done) or "E" (error) status line; the interpolator's outputs are recorded
// (only their changes) and replayed into the play monitors once the program is known: the
// frames the board received, read back by the software tape reader.
// The operator's events (--events) drive the board's pins (rtl/board/operator_pins.sv): a
// button is held down for three of its debounce sample periods from the event's clock, a
// stop switch stays tripped, the optional stop switch keeps its level. A run that pauses
// (M00, M01) with no cycle start to come ends there.
#pragma once
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "operator_events.h"
#include "play_run.h"
#include "tape.h"

namespace ncinterp::board {

// The flow control the chip honours: RTS/CTS, XON/XOFF, or none (the sender counts the
// board's ACKs: character counting, which lets realtime bytes through a held machine).
enum class Flow { kRtsCts, kXonXoff, kCount };
Flow flow_named(const std::string& name);  // "rtscts", "xonxoff", "count"
const char* flow_name(Flow f);

struct BoardSimOptions {
  std::string board = "icestick";
  double accel_mm_s2 = -1;    // the feed ramp's limit; < 0: the board's own, 0: none
  double rapid_mm_min = kDefaultRapidMmMin;  // the rapid rate (board_top's RapidMmMin)
  std::vector<OperatorEvent> events;  // on the board's pins (no overrides: no pins for them)
  double clock_hz = 12e6;
  unsigned baud = 115200;
  Flow flow = Flow::kRtsCts;
  std::string pty_link;       // symlink to the pty's slave, created and removed by the run
  std::string vcd_path;       // empty: no VCD
  uint64_t max_cycles = 0;    // 0: no limit
  double idle_timeout_s = 30;  // wall time without a byte while the board is idle
  // Step pulse timing, ns (board_top's parameters).
  double pulse_ns = 2000, low_ns = 2000, dir_setup_ns = 1000, dir_hold_ns = 1000;
};

struct BoardSimResult {
  system::PlayResult play;
  std::vector<uint8_t> frames;          // received by the board, EOT excluded
  tape::ParseResult readback;           // the frames read back by the software reader
  std::vector<std::string> status_lines;  // sent by the board, without CR LF
  uint8_t board_error = 0;              // board_core's own error code (0: none)
  unsigned max_fifo_level = 0;
  uint64_t flow_hold_cycles = 0;        // clocks a byte waited for CTS# low or XON
  uint64_t xoff_sent = 0;               // XOFF bytes the board sent
  uint64_t acks_sent = 0;               // ACK bytes the board sent
  std::vector<uint64_t> realtime;       // the realtime commands the board took, per command
  uint16_t bit_cycles = 0;
  bool timed_out = false;               // the sender went quiet before the end
  bool paused = false;                  // paused with no cycle start to come
};

// The static configuration board_top computes from its parameters, for a clock and baud.
struct CoreConfig {
  uint16_t bit_cycles = 0;
  uint64_t feed_modulus = 0;
  uint8_t setup_cycles = 0, pulse_cycles = 0, low_cycles = 0;
};
CoreConfig core_config(const BoardSimOptions& o);

// Runs the board until it reports done or an error (or the cycle limit or the idle
// timeout). `on_ready(path)` is called once the pty link exists. Throws
// std::runtime_error for unusable options or a pty that cannot be made.
BoardSimResult run_board_sim(const BoardSimOptions& options,
                             const std::function<void(const std::string&)>& on_ready);

// The report: play's JSON fields (sc_model/system/play_report.h) plus a "board" object.
nlohmann::json board_sim_report(const BoardSimResult& r, const BoardSimOptions& o);

}  // namespace ncinterp::board
