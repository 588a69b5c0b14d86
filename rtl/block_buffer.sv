// Block buffer: the one-deep "next block" register between the tape decoder and the player.
//
// What: while the current block plays, the next decoded block waits here, so the decoder
// can go on reading the tape and blocks follow without gaps when the reader is fast
// enough. The block is an opaque bit vector (interp_top packs and unpacks the fields).
// Timing: in_ready_o = empty (a register), so a block is taken at an edge where the
// buffer is empty, never in the edge that empties it; pop_i empties it at that edge.
// Golden twin: the section "Block buffer" of GoldenInterp::tick()
// (sc_model/golden/interp_top.h).
module block_buffer #(
  parameter int Width = 8
) (
  input  logic             clk_i,
  input  logic             rst_ni,
  input  logic             in_valid_i,
  output logic             in_ready_o,
  input  logic [Width-1:0] in_block_i,
  input  logic             pop_i,
  output logic             out_valid_o,
  output logic [Width-1:0] out_block_o
);

  // full_q: a block is waiting; block_q: that block (loaded only when one is taken).
  logic             full_q, full_d;
  logic [Width-1:0] block_q;
  logic             take;

  assign take = in_valid_i && !full_q;

  always_comb begin
    full_d = full_q;
    if (full_q) begin
      if (pop_i) full_d = 1'b0;
    end else if (in_valid_i) begin
      full_d = 1'b1;
    end
  end

  always_ff @(posedge clk_i) begin
    if (!rst_ni) begin
      full_q  <= 1'b0;
      block_q <= '0;
    end else begin
      full_q <= full_d;
      if (take) block_q <= in_block_i;
    end
  end

  assign in_ready_o  = !full_q;
  assign out_valid_o = full_q;
  assign out_block_o = block_q;

endmodule
