// Formal harness of the block buffer (rtl/block_buffer.sv), the valid/ready stage between
// the tape decoder and the player.
//
// What is proven:
// - ap_taken: a block offered while the buffer is ready is the one it then holds
//   (out_valid, out_block = the offered block), and a block is taken only when ready;
//   in block RAM (InRam) it is valid one edge later (the RAM's registered read);
// - ap_held: a held block stays unchanged and valid until it is popped;
// - ap_ready: ready = empty (never taken in the edge that empties it);
// - ap_popped: a pop empties the buffer.
// Environment: reset in the first clock; the producer may offer anything at any time; pop
// only while a block is valid (interp_top loads only a valid block). The harness keeps its
// own copy of the held block (a one-entry queue model). The register is proven by
// k-induction on the ports; the RAM by BMC (an induction would start from RAM contents no
// run can reach, and the ports cannot constrain them).
module block_buffer_props #(
  parameter int B     = 4,
  parameter bit InRam = 1'b0
) (
  input logic         clk_i,
  input logic         rst_ni,
  input logic         in_valid_i,
  input logic [B-1:0] in_block_i,
  input logic         pop_i
);

  logic         in_ready, out_valid;
  logic [B-1:0] out_block;

  block_buffer #(.Width(B), .InRam(InRam), .FlopBits(1)) u_dut (
    .clk_i, .rst_ni, .in_valid_i, .in_ready_o(in_ready), .in_block_i, .pop_i,
    .out_valid_o(out_valid), .out_block_o(out_block)
  );

  // The model queue: f_full_q holds f_block_q, taken at the last edge if f_fresh_q.
  logic         f_init = 1'b1;
  logic         f_full_q, f_fresh_q;
  logic [B-1:0] f_block_q;

  always_ff @(posedge clk_i) begin
    f_init <= 1'b0;
    f_fresh_q <= 1'b0;
    if (!rst_ni) begin
      f_full_q <= 1'b0;
      f_block_q <= '0;
    end else if (f_full_q) begin
      if (pop_i) f_full_q <= 1'b0;
    end else if (in_valid_i) begin
      f_full_q <= 1'b1;
      f_fresh_q <= 1'b1;
      f_block_q <= in_block_i;
    end
  end

  always_comb begin
    if (f_init) assume (!rst_ni);
    if (pop_i) assume (out_valid);
  end

  always_comb begin
    if (!f_init) begin
      ap_ready: assert (in_ready == !f_full_q);
      ap_taken: assert (out_valid == (f_full_q && !(InRam && f_fresh_q)));
      if (out_valid) ap_held: assert (out_block == f_block_q);
    end
  end

  // ap_popped and a $past view of ap_held: after a pop the buffer is empty, unless a new
  // block was taken in a later edge.
  logic f_past_valid = 1'b0;
  always_ff @(posedge clk_i) begin
    f_past_valid <= 1'b1;
    if (f_past_valid && $past(rst_ni)) begin
      if ($past(out_valid && pop_i)) ap_popped: assert (!out_valid);
      if ($past(out_valid && !pop_i)) ap_stable: assert (out_valid && $stable(out_block));
    end
  end

  always_comb begin
    if (!f_init) cp_refill: cover (out_valid && f_block_q == {B{1'b1}});
  end

endmodule
