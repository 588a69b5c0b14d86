// Formal harness of the block buffer (rtl/block_buffer.sv), the valid/ready stage between
// the tape decoder and the player.
//
// What is proven:
// - ap_taken: a block offered while the buffer is ready is the one it then holds
//   (out_valid, out_block = the offered block), and a block is taken only when ready;
//   in block RAM (InRam) it is valid one edge later (the RAM's registered read);
// - ap_held: a held block stays unchanged and valid until it is popped;
// - ap_ready: ready = empty (never taken in the edge that empties it);
// - ap_popped: a pop empties the buffer;
// - ap_words (InRam): while hold_i, the popped block's RAM part is still what out_block
//   shows (the bit-serial player reads its words from there), and no block is valid;
// - ap_play: from the edge after a pop, out_play shows the popped block's low bits (the
//   feed generator's S).
// Environment: reset in the first clock; the producer may offer anything at any time; pop
// only while a block is valid (interp_top loads only a valid block); hold_i rises only at
// a pop and, once it falls, stays low until the next one (the player's words_o). The
// harness keeps its own copy of the held block (a one-entry queue model) and of the popped
// one. The register is proven by k-induction on the ports; the RAM by BMC (an induction
// would start from RAM contents no run can reach, and the ports cannot constrain them).
module block_buffer_props #(
  parameter int B     = 4,
  parameter bit InRam = 1'b0
) (
  input logic         clk_i,
  input logic         rst_ni,
  input logic         in_valid_i,
  input logic [B-1:0] in_block_i,
  input logic         pop_i,
  input logic         hold_i
);

  logic         in_ready, out_valid;
  logic [B-1:0] out_block;
  logic [B-2:0] out_play;

  block_buffer #(.Width(B), .InRam(InRam), .FlopBits(1), .PlayBits(B - 1)) u_dut (
    .clk_i, .rst_ni, .in_valid_i, .in_ready_o(in_ready), .in_block_i, .pop_i, .hold_i,
    .out_valid_o(out_valid), .out_block_o(out_block), .out_play_o(out_play)
  );

  // The model queue: f_full_q holds f_block_q. f_unshown_q: with the RAM, its read register
  // did not read the held block's slot at the last edge (a block was taken then, or the
  // popped block was held). f_popped_q: the block popped last; f_may_hold_q: hold_i may be
  // high (it has been since that pop).
  logic         f_init = 1'b1;
  logic         f_full_q, f_unshown_q, f_may_hold_q, f_played_q;
  logic [B-1:0] f_block_q, f_popped_q;

  always_ff @(posedge clk_i) begin
    f_init <= 1'b0;
    f_unshown_q <= hold_i && f_full_q;
    f_may_hold_q <= (f_may_hold_q && hold_i) || (f_full_q && pop_i);
    if (!rst_ni) begin
      f_full_q <= 1'b0;
      f_block_q <= '0;
      f_popped_q <= '0;
      f_may_hold_q <= 1'b0;
      f_played_q <= 1'b0;
    end else if (f_full_q) begin
      if (pop_i) begin
        f_full_q <= 1'b0;
        f_popped_q <= f_block_q;
        f_played_q <= 1'b1;
      end
    end else if (in_valid_i) begin
      f_full_q <= 1'b1;
      f_unshown_q <= 1'b1;
      f_block_q <= in_block_i;
    end
  end

  always_comb begin
    if (f_init) assume (!rst_ni);
    if (pop_i) assume (out_valid);
    if (hold_i) assume (f_may_hold_q && rst_ni);
  end

  always_comb begin
    if (!f_init) begin
      ap_ready: assert (in_ready == !f_full_q);
      ap_taken: assert (out_valid == (f_full_q && !(InRam && (f_unshown_q || hold_i))));
      if (out_valid) ap_held: assert (out_block == f_block_q);
      if (InRam && hold_i) ap_words: assert (out_block[B-2:0] == f_popped_q[B-2:0]);
      if (f_played_q) ap_play: assert (out_play == f_popped_q[B-2:0]);
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
    if (!f_init) begin
      cp_refill: cover (out_valid && f_block_q == {B{1'b1}});
      cp_taken_while_held: cover (hold_i && f_full_q && f_popped_q != f_block_q);
    end
  end

endmodule
