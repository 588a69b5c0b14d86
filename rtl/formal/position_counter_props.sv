// Formal harness of the position counter (rtl/position_counter.sv).
//
// What is proven: ap_pos: the counter always equals the pulses counted up minus the pulses
// counted down since reset (modulo 2^PosWidth, the documented wrap), each pulse counted at
// the edge where it is emitted. The harness counts ups and downs in two counters of its own.
// Environment: reset in the first clock, any pulses and directions afterwards (and resets).
// Proven by k-induction straight from the ports.
module position_counter_props #(
  parameter int P = 4
) (
  input logic clk_i,
  input logic rst_ni,
  input logic count_i,
  input logic up_i
);

  logic [P-1:0] pos;

  position_counter #(.PosWidth(P)) u_dut (.clk_i, .rst_ni, .count_i, .up_i, .pos_o(pos));

  // f_ups_q, f_downs_q: pulses counted each way since reset.
  logic         f_init = 1'b1;
  logic [P-1:0] f_ups_q, f_downs_q;

  always_ff @(posedge clk_i) begin
    f_init <= 1'b0;
    if (!rst_ni) begin
      f_ups_q <= '0;
      f_downs_q <= '0;
    end else if (count_i) begin
      if (up_i) f_ups_q <= f_ups_q + 1'b1;
      else f_downs_q <= f_downs_q + 1'b1;
    end
  end

  always_comb begin
    if (f_init) assume (!rst_ni);
    if (!f_init) ap_pos: assert (pos == f_ups_q - f_downs_q);
  end

  always_comb begin
    if (!f_init) cp_down_and_up: cover (f_ups_q == P'(2) && f_downs_q == P'(3));
  end

endmodule
