// Operator pins: the board's feed hold and cycle start buttons and its E-stop, limit and
// optional stop switches, brought into the clock domain as interp_top's operator inputs.
//
// What: every pin passes a two-flip-flop synchronizer (the pins are asynchronous to the
// clock). The stops (E-stop, limits) act on the first synchronized high: interp_top latches
// them, so a glitch can only stop the machine, never let it run on, and no filter delays a
// stop (two clocks here, then interp_top's own latency, docs/motion-control.md 3). The
// optional stop switch is a level, read only at an M01's end. The two buttons are
// debounced, because a bounce would be a second press (a hold and at once a resume): a
// shared prescaler samples them every 2^DebounceWidth clocks, and a button is down once
// two samples in a row saw it down (up likewise). Its going down is one clock of hold_o or
// start_o, the press interp_top takes. A press is seen 2^DebounceWidth to 2^(DebounceWidth
// + 1) + 3 clocks after the button goes down (5.5 to 11 ms at 12 MHz and 16 bits; a
// contact bounces for a few ms); a shorter press is not one.
// Inputs are active high (pressed, tripped, on): board_top turns each pin's polarity.
// Timing: every output is a register.
// Golden twin: OperatorPinsModel (sc_model/board/operator_pins_model.h).
module operator_pins #(
  parameter int DebounceWidth = 16
) (
  input  logic clk_i,
  input  logic rst_ni,
  input  logic hold_i,
  input  logic start_i,
  input  logic estop_i,
  input  logic limit_x_i,
  input  logic limit_y_i,
  input  logic optional_stop_i,
  output logic hold_o,
  output logic start_o,
  output logic estop_o,
  output logic limit_x_o,
  output logic limit_y_o,
  output logic optional_stop_o
);

  // The pins in synchronizer order: {optional stop, limit y, limit x, E-stop, start, hold}.
  localparam int Pins = 6;
  logic [Pins-1:0] meta_q, sync_q;
  // The buttons (hold, start): the last sample, the debounced level, the press.
  logic [1:0] sample_q, down_q, press_q;
  logic [DebounceWidth-1:0] prescale_q;
  logic tick;

  assign tick = &prescale_q;

  always_ff @(posedge clk_i) begin
    if (!rst_ni) begin
      meta_q     <= '0;
      sync_q     <= '0;
      sample_q   <= '0;
      down_q     <= '0;
      press_q    <= '0;
      prescale_q <= '0;
    end else begin
      meta_q     <= {optional_stop_i, limit_y_i, limit_x_i, estop_i, start_i, hold_i};
      sync_q     <= meta_q;
      prescale_q <= prescale_q + 1'b1;
      press_q    <= '0;
      if (tick) begin
        sample_q <= sync_q[1:0];
        for (int b = 0; b < 2; b++) begin
          if (sync_q[b] == sample_q[b]) begin
            down_q[b]  <= sync_q[b];
            press_q[b] <= sync_q[b] && !down_q[b];
          end
        end
      end
    end
  end

`ifndef SYNTHESIS
  // Checked at every edge of every verilated run: a press comes only with its button down
  // and lasts one clock (the next tick is 2^DebounceWidth clocks away), the one clock of
  // hold_i or start_i that interp_top takes for a press.
  logic [1:0] press_prev_q;
  always_ff @(posedge clk_i) begin
    press_prev_q <= press_q;
    if (rst_ni) begin
      a_press_when_down: assert ((press_q & ~down_q) == '0);
      a_press_one_clock: assert ((press_q & press_prev_q) == '0);
    end
  end
`endif

  assign hold_o          = press_q[0];
  assign start_o         = press_q[1];
  assign estop_o         = sync_q[2];
  assign limit_x_o       = sync_q[3];
  assign limit_y_o       = sync_q[4];
  assign optional_stop_o = sync_q[5];

endmodule
