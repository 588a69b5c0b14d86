// Operator pins: the board's buttons (feed hold, cycle start, the feed override's +10 %,
// -10 % and 100 %, the rapid override's step) and its E-stop, limit and optional stop
// switches, brought into the clock domain as interp_top's operator inputs.
//
// What: every pin passes a two-flip-flop synchronizer (the pins are asynchronous to the
// clock). The stops (E-stop, limits) act on the first synchronized high: interp_top latches
// them, so a glitch can only stop the machine, never let it run on, and no filter delays a
// stop (two clocks here, then interp_top's own latency, docs/motion-control.md 3). The
// optional stop switch is a level, read only at an M01's end. The buttons are debounced,
// because a bounce would be a second press (a hold and at once a resume, two override
// steps): a shared prescaler samples them every 2^DebounceWidth clocks, and a button is
// down once two samples in a row saw it down (up likewise). Its going down is one press. A
// press is seen 2^DebounceWidth to 2^(DebounceWidth + 1) + 3 clocks after the button goes
// down (5.5 to 11 ms at 12 MHz and 16 bits; a contact bounces for a few ms); a shorter
// press is not one. Hold and start give one clock of hold_o or start_o, the press
// interp_top takes. The feed override counts tens of percent, 0 to 200 % (10 % at reset),
// and its output is interp_pkg::override_of_tens() of the count, the rounding of the
// command line's override=P; the rapid override steps 100, 50, 25, 100 % ... (ISO's and
// grbl's steps).
// The host's realtime commands (remote_i, host_link.sv) are presses too, one clock each, in
// interp_pkg::realtime_command()'s order: the buttons', then the E-stop, which stops the
// machine as the switch does (interp_top latches it).
// Inputs are active high (pressed, tripped, on): board_top turns each pin's polarity.
// Timing: every output is a register (the rapid override: a constant shifted by one; the
// E-stop: the OR of the pin's and the host's).
// Golden twin: OperatorPinsModel (sc_model/board/operator_pins_model.h).
module operator_pins #(
  parameter int DebounceWidth = interp_pkg::OperatorDebounceWidth
) (
  input  logic clk_i,
  input  logic rst_ni,
  input  logic hold_i,
  input  logic start_i,
  input  logic feed_up_i,
  input  logic feed_down_i,
  input  logic feed_reset_i,
  input  logic rapid_cycle_i,
  input  logic estop_i,
  input  logic limit_x_i,
  input  logic limit_y_i,
  input  logic optional_stop_i,
  input  logic [interp_pkg::RealtimeCommands-1:0] remote_i,
  output logic hold_o,
  output logic start_o,
  output logic [interp_pkg::OverrideWidth-1:0] feed_override_o,
  output logic [interp_pkg::OverrideWidth-1:0] rapid_override_o,
  output logic estop_o,
  output logic limit_x_o,
  output logic limit_y_o,
  output logic optional_stop_o
);

  // The pins in synchronizer order: the buttons first, then the switches.
  localparam int Buttons = 6, Pins = 10;
  localparam int BHold = 0, BStart = 1, BFeedUp = 2, BFeedDown = 3, BFeedReset = 4, BRapid = 5;
  localparam int SEStop = 6, SLimitX = 7, SLimitY = 8, SOptionalStop = 9;
  logic [Pins-1:0] meta_q, sync_q;
  // The buttons: the last sample, the debounced level, a pin's press, any press (the pin's
  // or the host's).
  logic [Buttons-1:0] sample_q, down_q, pin_press, press, press_q;
  logic               remote_estop_q;
  logic [DebounceWidth-1:0] prescale_q;
  logic tick;
  // The feed override in tens of percent; the rapid override's step (0: 100 %, 1: 50 %,
  // 2: 25 %); both outputs.
  localparam logic [4:0] TensAtOne = 5'(interp_pkg::OverrideTensAtOne);
  logic [4:0] tens_q, tens_d;
  logic [1:0] rapid_q, rapid_d;
  logic [interp_pkg::OverrideWidth-1:0] feed_override_q;

  assign tick = &prescale_q;

  always_comb begin
    for (int b = 0; b < Buttons; b++)
      pin_press[b] = tick && sync_q[b] && sample_q[b] && !down_q[b];
    press = pin_press | remote_i[Buttons-1:0];
    tens_d = press[BFeedReset]                                         ? TensAtOne
           : press[BFeedUp] && tens_q != 5'(interp_pkg::OverrideTens) ? tens_q + 1'b1
           : press[BFeedDown] && tens_q != '0                          ? tens_q - 1'b1
           :                                                             tens_q;
    rapid_d = !press[BRapid] ? rapid_q : rapid_q == 2'd2 ? 2'd0 : rapid_q + 1'b1;
  end

  always_ff @(posedge clk_i) begin
    if (!rst_ni) begin
      meta_q          <= '0;
      sync_q          <= '0;
      sample_q        <= '0;
      down_q          <= '0;
      press_q         <= '0;
      remote_estop_q  <= 1'b0;
      prescale_q      <= '0;
      tens_q          <= TensAtOne;
      rapid_q         <= '0;
      feed_override_q <= interp_pkg::OverrideOne;
    end else begin
      meta_q     <= {optional_stop_i, limit_y_i, limit_x_i, estop_i, rapid_cycle_i, feed_reset_i,
                     feed_down_i, feed_up_i, start_i, hold_i};
      sync_q     <= meta_q;
      prescale_q <= prescale_q + 1'b1;
      press_q    <= press;
      remote_estop_q <= remote_i[Buttons];
      if (tick) begin
        sample_q <= sync_q[Buttons-1:0];
        for (int b = 0; b < Buttons; b++)
          if (sync_q[b] == sample_q[b]) down_q[b] <= sync_q[b];
      end
      tens_q          <= tens_d;
      rapid_q         <= rapid_d;
      feed_override_q <= interp_pkg::override_of_tens(tens_d);
    end
  end

`ifndef SYNTHESIS
  // Checked at every edge of every verilated run: a pin's press comes only with its button
  // down and lasts one clock (the next tick is 2^DebounceWidth clocks away), and so does
  // the host's (its pairs of bytes are a byte time apart): the one clock of hold_i or start_i
  // that interp_top takes for a press; the overrides stay in range.
  logic [Buttons-1:0] pin_press_q, press_prev_q;
  always_ff @(posedge clk_i) begin
    pin_press_q  <= pin_press;
    press_prev_q <= press_q;
    if (rst_ni) begin
      a_press_when_down: assert ((pin_press_q & ~down_q) == '0);
      a_press_one_clock: assert ((press_q & press_prev_q) == '0);
      a_override_range: assert (tens_q <= 5'(interp_pkg::OverrideTens) && rapid_q != 2'd3);
    end
  end
`endif

  assign hold_o           = press_q[BHold];
  assign start_o          = press_q[BStart];
  assign feed_override_o  = feed_override_q;
  assign rapid_override_o = interp_pkg::OverrideOne >> rapid_q;
  assign estop_o          = sync_q[SEStop] || remote_estop_q;
  assign limit_x_o        = sync_q[SLimitX];
  assign limit_y_o        = sync_q[SLimitY];
  assign optional_stop_o  = sync_q[SOptionalStop];

endmodule
