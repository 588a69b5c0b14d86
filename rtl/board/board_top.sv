// Pin-level board top shared by the iCEstick and the iCEBreaker: board_core with its
// static configuration computed from the board clock and the user's parameters, a
// power-on reset, and the pins named as in rtl/board/<board>.pcf. The board's core
// configuration (arch, circle mode) is a parameter: `ncinterp bitstream` sets each board's
// (sw/tools/bitstream/bitstream.cpp: the iCEstick's HX1K takes the serial core without
// circle mode, the iCEBreaker the whole one).
//
// What: the board's oscillator clocks everything directly (no PLL: 12 MHz is ample for
// the interpolator, docs/board.md), and feed_modulus = 60 * ClockHz * 10^3 makes every
// block last its programmed 1/F minute. The reset is held for 15 clocks after
// configuration (the iCE40's flip-flops start at their initial values). LEDs are active
// high or low (LedActiveLow, a bit per LED); step/dir and the tool output go to the PMOD
// header.
// Step timing parameters (ns) and what drivers need (docs/board.md): DRV8825 STEP high and
// low >= 1.9 us, DIR setup and hold >= 650 ns; TB6600 (TB67S109-based modules) pulse >= 2.5 us,
// DIR >= 5 us ahead of the pulse. The defaults suit the DRV8825 (2 us pulse, 1 us setup).
// Golden twin: board_core's (rtl/board/board_core.sv: GoldenInterp and the board models of
// sc_model/board/); the pins and the power-on reset have none, and `ncinterp board-sim`
// verilates board_core with the configuration computed here (sc_model/board/boards.h).
module board_top #(
  parameter int     ClockHz    = 12_000_000,
  parameter int     Baud       = 115_200,
  parameter int     PulseNs    = 2_000,
  parameter int     LowNs      = 2_000,
  parameter int     DirSetupNs = 1_000,
  parameter int     DirHoldNs  = 1_000,
  // Which LEDs light on a low pin, {error, done, busy}: the iCEBreaker's red and green (on
  // the main board); its break-off board's and the iCEstick's light on a high pin.
  parameter logic [2:0] LedActiveLow = 3'b000,
  // The interpolator's configuration (interp_top's BitSerial, CircleMode, MiscFunctions;
  // AccelMmS2 below is its Accel).
  parameter bit     BitSerial  = 1'b1,
  parameter bit     CircleMode = 1'b1,
  parameter bit     MiscFunctions = 1'b1,
  // The machine's rapid rate (G00), mm/min.
  parameter int     RapidMmMin = 5000,
  // The feed ramp's acceleration limit, mm/s^2 (docs/motion-control.md); 0 builds no ramp.
  parameter int     AccelMmS2  = 500,
  // The operator's pins (board_core's OperatorPins), and which of them are active high (a
  // button with a pull-down), in the order {optional stop, limit y, limit x, E-stop, rapid
  // override step, feed override 100 %, -10 %, +10 %, start, hold}; the others are active
  // low (a contact to GND, the pin's pull-up in the .pcf).
  parameter bit     OperatorPins = 1'b1,
  parameter logic [9:0] OperatorActiveHigh = 10'b0001000011
) (
  input  logic clk_i,
  input  logic uart_rx_i,
  output logic uart_tx_o,
  output logic uart_cts_no,
  output logic step_x_o,
  output logic dir_x_o,
  output logic step_y_o,
  output logic dir_y_o,
  output logic tool_o,
  // The operator's buttons and switches (OperatorActiveHigh says each one's polarity).
  input  logic hold_pin_i,
  input  logic start_pin_i,
  input  logic feed_up_pin_i,
  input  logic feed_down_pin_i,
  input  logic feed_reset_pin_i,
  input  logic rapid_cycle_pin_i,
  input  logic estop_pin_i,
  input  logic limit_x_pin_i,
  input  logic limit_y_pin_i,
  input  logic optional_stop_pin_i,
  output logic led_busy_o,
  output logic led_done_o,
  output logic led_error_o
);

  `include "board_timing.svh"

  localparam logic [15:0] BitCycles   = baud_to_cycles(Baud, ClockHz);
  localparam logic [15:0] PulseCycles = ns_to_cycles(PulseNs, ClockHz);
  localparam logic [15:0] SetupCycles = ns_to_cycles(DirSetupNs, ClockHz);
  // dir_o is held pulse + low clocks after the rising edge: low covers what hold needs.
  localparam logic [15:0] HoldLow     = ns_to_cycles(DirHoldNs, ClockHz) > PulseCycles ?
                                        ns_to_cycles(DirHoldNs, ClockHz) - PulseCycles : 16'd1;
  localparam logic [15:0] LowCycles   = ns_to_cycles(LowNs, ClockHz) > HoldLow ?
                                        ns_to_cycles(LowNs, ClockHz) : HoldLow;
  // M = 60 * ClockHz * 10^3 (FeedFracDigits 3), as wide as it needs.
  localparam longint FeedModulus  = 64'(ClockHz) * 64'd60_000;
  localparam int     ModulusWidth = $clog2(FeedModulus + 1);
  // rapid_step_i: the rapid rate in BLU/min (FracDigits 3) times 10^3 (FeedFracDigits 3).
  localparam longint RapidStep    = 64'(RapidMmMin) * 64'd1_000_000;
  // accel_step_i: du = A 10^FracDigits M / f^2, rounded down (InterpConfig::accel_step_for()).
  localparam longint AccelStep    = 64'(AccelMmS2) * 64'd1_000 * FeedModulus /
                                    (64'(ClockHz) * 64'(ClockHz));
  // The UART's bit counter and the stretchers' counters as wide as these constants (their
  // ports carry them): 7 and 5 bits at 12 MHz, 115 200 baud and the default timing.
  localparam int DivWidth     = $clog2(32'(BitCycles) + 1);
  localparam logic [15:0] MaxStretch = SetupCycles > PulseCycles ?
                                       (SetupCycles > LowCycles ? SetupCycles : LowCycles) :
                                       (PulseCycles > LowCycles ? PulseCycles : LowCycles);
  localparam int StretchWidth = $clog2(32'(MaxStretch) + 1);

  // por_q: counts clocks after configuration; the core leaves reset when it saturates.
  logic [3:0] por_q = '0;
  always_ff @(posedge clk_i) if (por_q != 4'hf) por_q <= por_q + 1'b1;

  logic led_busy, led_done, led_error;
  assign led_busy_o  = led_busy ^ LedActiveLow[0];
  assign led_done_o  = led_done ^ LedActiveLow[1];
  assign led_error_o = led_error ^ LedActiveLow[2];

  // The pins as board_core takes them: high when pressed, tripped or on.
  logic [9:0] operator;
  assign operator = {optional_stop_pin_i, limit_y_pin_i, limit_x_pin_i, estop_pin_i, rapid_cycle_pin_i,
                     feed_reset_pin_i, feed_down_pin_i, feed_up_pin_i, start_pin_i,
                     hold_pin_i} ~^ OperatorActiveHigh;

  /* verilator lint_off PINCONNECTEMPTY */
  board_core #(
    .BitSerial(BitSerial), .CircleMode(CircleMode), .MiscFunctions(MiscFunctions),
    .Accel(AccelMmS2 != 0), .OperatorPins(OperatorPins), .ModulusWidth(ModulusWidth),
    .DivWidth(DivWidth), .StretchWidth(StretchWidth)
  ) u_core (
    .clk_i, .rst_ni(por_q == 4'hf),
    .bit_cycles_i(DivWidth'(BitCycles)), .feed_modulus_i(ModulusWidth'(FeedModulus)),
    .rapid_step_i(ModulusWidth'(RapidStep)), .accel_step_i(ModulusWidth'(AccelStep)),
    .setup_cycles_i(StretchWidth'(SetupCycles)), .pulse_cycles_i(StretchWidth'(PulseCycles)),
    .low_cycles_i(StretchWidth'(LowCycles)),
    .hold_i(operator[0]), .start_i(operator[1]), .feed_up_i(operator[2]), .feed_down_i(operator[3]),
    .feed_reset_i(operator[4]), .rapid_cycle_i(operator[5]), .estop_i(operator[6]),
    .limit_x_i(operator[7]), .limit_y_i(operator[8]), .optional_stop_i(operator[9]),
    .rx_i(uart_rx_i), .tx_o(uart_tx_o), .cts_no(uart_cts_no),
    .step_x_o, .dir_x_o, .step_y_o, .dir_y_o, .tool_o,
    .led_busy_o(led_busy), .led_done_o(led_done), .led_error_o(led_error),
    .obs_frame_ready_o(), .obs_step_x_o(), .obs_dir_x_o(), .obs_step_y_o(), .obs_dir_y_o(),
    .obs_pos_x_o(), .obs_pos_y_o(), .obs_block_n_o(), .obs_busy_o(), .obs_done_o(),
    .obs_error_o(), .obs_error_code_o(), .obs_error_block_o(), .obs_error_offset_o(),
    .obs_feed_saturated_o(), .obs_tool_o(), .obs_paused_o(), .obs_fifo_level_o(), .obs_rx_data_o(),
    .obs_rx_valid_o(), .obs_realtime_o(), .board_error_code_o()
  );
  /* verilator lint_on PINCONNECTEMPTY */

endmodule
