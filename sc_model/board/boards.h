// The boards the project builds for, one line each: the one definition that `ncinterp
// bitstream`, `board-sim`, `send` and `tape --board` read.
// Idea: a board is its part and pins, its clock, its USB-serial chip's flow control, and
// the interpolator configuration that fits its part (arch, circle mode): the iCEstick's
// HX1K holds the whole board only with the lines-only core (docs/board.md), the
// iCEBreaker's UP5K the whole interpolator.
#pragma once
#include <string>
#include <vector>

#include "interp_ports.h"

namespace ncinterp::board {

struct Board {
  std::string name;            // "icestick"
  std::string part;            // "HX1K"
  std::string pnr_part;        // nextpnr-ice40's option: "--hx1k"
  std::string package;         // "tq144"
  double clock_hz = 12e6;      // the oscillator
  bool dsp = false;            // the part has multipliers (synth_ice40 -dsp)
  unsigned led_active_low = 0; // board_top's LedActiveLow: {error, done, busy}, 1 = lit by a low pin
  std::string flow;            // its flow control (board_sim.h Flow): "rtscts", "xonxoff" or "count"
  Arch arch = Arch::kSerial;   // board_top's BitSerial
  bool circle_mode = true;     // board_top's CircleMode
  bool misc_functions = true;  // board_top's MiscFunctions (M00, M01, M03, M05)
  // board_top's AccelMmS2: the feed ramp's acceleration limit, mm/s^2; 0: no ramp built.
  double accel_mm_s2 = 0;
  // board_top's OperatorPins: feed hold, cycle start, E-stop, limit and optional stop pins.
  bool operator_pins = false;
};

const std::vector<Board>& boards();
// The board of that name; throws std::invalid_argument naming the boards otherwise.
const Board& board_named(const std::string& name);
// "icestick, icebreaker".
std::string board_names();

// The interpolator as board_core builds it for the board at clock_hz: its arch, circle
// mode, miscellaneous functions and feed ramp (accel_mm_s2 < 0: the board's own limit;
// 0: no ramp; refused where the board has none), the rapid rate (mm/min; board_top's
// RapidMmMin is the default), and board_core's widths (PosWidth, SeqWidth, OffsetWidth: 20 bits; the status line
// sends their low bits, sc_model/board/status_text.h).
InterpConfig board_interp_config(const Board& b, double clock_hz, double accel_mm_s2 = -1,
                                 double rapid_mm_min = kDefaultRapidMmMin);

}  // namespace ncinterp::board
