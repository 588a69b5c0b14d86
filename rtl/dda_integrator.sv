// One axis of the line DDA: an integrator whose carries are the axis's step pulses.
//
// What (method L1, normalised): for a block with k = bit length of max(|dx|, |dy|) the
// integrator starts at 2^(k-1) (half: round to nearest) and adds |d| at every iteration; a
// carry out of bit k is a step (and 2^k is subtracted). After 2^k iterations exactly |d|
// steps have come out, each within 1/2 BLU of the ideal point.
// Timing: load_i sets the block's increment, direction and start value; at an edge with
// iterate_i the carry (carry_o, combinational) becomes step_o for one clock. dir_o changes
// only at load edges, so it is valid in every clock with a step and held for the block.
// Golden twin: the section "Line DDA" of GoldenInterp::tick()
// (sc_model/golden/interp_top.h).
module dda_integrator #(
  parameter int Width = 16
) (
  input  logic           clk_i,
  input  logic           rst_ni,
  input  logic           load_i,
  input  logic [Width-1:0] start_i,    // 2^(k-1) of the loading block (0 for k = 0)
  input  logic [Width-1:0] inc_i,      // |d| of the loading block
  input  logic           neg_i,        // d < 0
  input  logic           iterate_i,    // one DDA iteration at this edge
  input  logic [Width:0] kpow_i,       // 2^k of the playing block (one-hot)
  output logic           carry_o,      // a step is emitted at this edge
  output logic           step_o,
  output logic           dir_o         // 1 = plus
);

  // acc_q: the integrator, in [0, 2^k). inc_q: |d|. step_q: the one-clock step pulse.
  // dir_q: the block's direction.
  logic [Width-1:0] acc_q, acc_d, inc_q, inc_d;
  logic             step_q, step_d, dir_q, dir_d;

  logic [Width:0] sum;

  always_comb begin
    sum     = '0;
    carry_o = 1'b0;
    acc_d   = acc_q;
    inc_d   = inc_q;
    dir_d   = dir_q;
    step_d  = 1'b0;
    if (load_i) begin
      acc_d = start_i;
      inc_d = inc_i;
      dir_d = !neg_i;
    end else if (iterate_i) begin
      sum     = {1'b0, acc_q} + {1'b0, inc_q};
      carry_o = |(sum & kpow_i);
      acc_d   = sum[Width-1:0] & ~kpow_i[Width-1:0];  // sum < 2^(k+1): clearing bit k subtracts 2^k
      step_d  = carry_o;
    end
  end

  always_ff @(posedge clk_i) begin
    if (!rst_ni) begin
      acc_q  <= '0;
      inc_q  <= '0;
      step_q <= 1'b0;
      dir_q  <= 1'b0;
    end else begin
      acc_q  <= acc_d;
      inc_q  <= inc_d;
      step_q <= step_d;
      dir_q  <= dir_d;
    end
  end

  assign step_o = step_q;
  assign dir_o  = dir_q;

endmodule
