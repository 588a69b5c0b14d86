// Position counter of one axis: counts the emitted step pulses, +1 or -1 by direction.
//
// What: a signed up/down counter in BLU that wraps at PosWidth bits (two's complement).
// Timing: it counts at the same edge as the step register is set, so after an edge the
// step output and the position that includes it appear together.
// Golden twin: the section "Position counters" of GoldenInterp::tick()
// (sc_model/golden/interp_top.h).
module position_counter #(
  parameter int PosWidth = 32
) (
  input  logic                clk_i,
  input  logic                rst_ni,
  input  logic                count_i,  // a pulse is emitted at this edge
  input  logic                up_i,     // its direction: 1 = plus
  output logic [PosWidth-1:0] pos_o
);

  // pos_q: pulses counted since reset (plus minus minus).
  logic [PosWidth-1:0] pos_q, pos_d;

  // One adder for both directions: pos + 1 or pos + (-1), the addend's upper bits ~up_i
  // (one LUT and one carry per bit on an iCE40, where +1 and -1 apart and a multiplexer
  // took nearly three).
  always_comb begin
    pos_d = pos_q;
    if (count_i) pos_d = pos_q + {{(PosWidth - 1){!up_i}}, 1'b1};
  end

  always_ff @(posedge clk_i) begin
    if (!rst_ni) pos_q <= '0;
    else pos_q <= pos_d;
  end

  assign pos_o = pos_q;

endmodule
