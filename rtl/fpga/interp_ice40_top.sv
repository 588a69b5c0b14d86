// iCE40 board top of the interpolator (HX1K, e.g. the iCEstick): interp_top with the pins
// a board needs and the feed modulus fixed at elaboration.
//
// What: clock, reset, the tape reader's frame/valid/ready/tape_end, step and dir of both
// axes, and busy / done / error (+ the 4-bit error code) for LEDs. The static feed modulus
// M = 60 * ClockHz * 10^FeedFracDigits is a parameter tied to feed_modulus_i, so synthesis
// folds it into the feed generator's compare instead of holding it in flip-flops. The
// position counters, N and the error's block and offset are not brought out (a board's
// drives count the steps themselves; the error's place on tape is for the simulators), so
// synthesis removes the logic that only feeds them; everything that decides the steps,
// their timing and the error behaviour stays.
// Timing: pass-through; every interp_top output is already a register.
module interp_ice40_top #(
  parameter int IncWidth       = 16,
  parameter int FeedWidth      = 32,
  parameter int FeedFracDigits = 3,
  parameter int SeqWidth       = 17,   // N <= 99 999
  // The board's clock (the iCEstick has a 12 MHz oscillator).
  parameter longint ClockHz    = 12_000_000,
  // The per-block arithmetic bit-serial, as on the board (rtl/board/board_core.sv).
  parameter bit BitSerial   = 1'b1,
  // Circle mode built in (interp_top's CircleMode).
  parameter bit CircleMode  = 1'b1,
  // The machine's rapid rate (G00), mm/min.
  parameter int RapidMmMin  = 5000,
  // The feed ramp's acceleration limit, mm/s^2 (0: no ramps; interp_top's Accel is built
  // only when it is set).
  parameter int AccelMmS2   = 0
) (
  input  logic       clk_i,
  input  logic       rst_ni,
  input  logic [7:0] frame_i,
  input  logic       frame_valid_i,
  input  logic       tape_end_i,
  output logic       frame_ready_o,
  output logic       step_x_o,
  output logic       dir_x_o,
  output logic       step_y_o,
  output logic       dir_y_o,
  output logic       busy_o,
  output logic       done_o,
  output logic       error_o,
  output logic [interp_pkg::ErrCodeWidth-1:0] error_code_o
);

  localparam longint FeedScale    = FeedFracDigits == 0 ? 1 : FeedFracDigits == 1 ? 10 :
                                    FeedFracDigits == 2 ? 100 : FeedFracDigits == 3 ? 1000 :
                                    10000;
  localparam longint FeedModulus  = 60 * ClockHz * FeedScale;
  localparam int     ModulusWidth = $clog2(FeedModulus + 1);
  // rapid_step_i: the rapid rate in BLU/min (FracDigits 3) times 10^FeedFracDigits.
  localparam longint RapidStep    = 64'(RapidMmMin) * 1000 * FeedScale;
  // du = A 10^FracDigits M / f^2 (InterpConfig::accel_step_for(), FracDigits 3), rounded down.
  localparam longint AccelStep    = 64'(AccelMmS2) * 1000 * FeedModulus / (ClockHz * ClockHz);

  // Not brought out (see the header).
  /* verilator lint_off UNUSEDSIGNAL */
  logic [15:0]         pos_x, pos_y;
  logic [SeqWidth-1:0] block_n, error_block;
  logic [15:0]         error_offset;
  logic                feed_saturated, tool, paused;
  /* verilator lint_on UNUSEDSIGNAL */

  interp_top #(
    .IncWidth(IncWidth), .FeedWidth(FeedWidth), .FeedFracDigits(FeedFracDigits),
    .PosWidth(16), .SeqWidth(SeqWidth), .OffsetWidth(16), .ModulusWidth(ModulusWidth),
    .BitSerial(BitSerial), .CircleMode(CircleMode), .Accel(AccelMmS2 != 0)
  ) u_interp (
    .clk_i, .rst_ni,
    .feed_modulus_i(ModulusWidth'(FeedModulus)), .rapid_step_i(ModulusWidth'(RapidStep)),
    .accel_step_i(ModulusWidth'(AccelStep)), .hold_i(1'b0), .start_i(1'b0),
    .feed_override_i(interp_pkg::OverrideOne), .rapid_override_i(interp_pkg::OverrideOne),
    .estop_i(1'b0), .limit_x_i(1'b0), .limit_y_i(1'b0), .optional_stop_i(1'b0),
    .frame_i, .frame_valid_i, .tape_end_i, .frame_ready_o,
    .step_x_o, .dir_x_o, .step_y_o, .dir_y_o,
    .pos_x_o(pos_x), .pos_y_o(pos_y),
    .block_n_o(block_n), .busy_o, .done_o, .error_o, .error_code_o,
    .error_block_o(error_block), .error_offset_o(error_offset),
    .feed_saturated_o(feed_saturated), .tool_o(tool), .paused_o(paused)
  );

endmodule
