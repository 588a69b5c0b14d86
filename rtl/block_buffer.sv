// Block buffer: the one-deep "next block" store between the tape decoder and the player.
//
// What: while the current block plays, the next decoded block waits here, so the decoder
// can go on reading the tape and blocks follow without gaps when the reader is fast
// enough. The block is an opaque bit vector (interp_top packs and unpacks the fields).
// Two ways to hold it (InRam):
//   0: a register of Width flip-flops;
//   1: a block RAM (the board's choice, with interp_top's BitSerial): Width flip-flops are
//      Width logic cells on an iCE40, while its block RAMs (16 on the HX1K) sit idle. The
//      RAM has two slots used in turn (the block taken is written to the slot not being
//      read, so no edge reads and writes one address) and a registered read of the slot
//      last written, every clock. The top FlopBits bits stay in flip-flops beside it:
//      interp_top puts N there, which a board leaves unused, so synthesis removes N's
//      logic (it cannot see through a RAM which of its bits are read).
// Timing: in_ready_o = empty (a register), so a block is taken at an edge where the
// buffer is empty, never in the edge that empties it; pop_i empties it at that edge.
// out_valid_o: the block can be read (and popped): from the edge after the take with the
// register; with the RAM one edge later, when the registered read has fetched it.
// Golden twin: the section "Block buffer" of GoldenInterp::tick()
// (sc_model/golden/interp_top.h), whose next_readable() is the RAM's extra clock.
module block_buffer #(
  parameter int Width    = 8,
  parameter bit InRam    = 1'b0,
  parameter int FlopBits = 1    // with InRam: 1 .. Width - 1
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

  // full_q: a block is held; fresh_q: it was taken at the last edge (not yet readable
  // from the RAM). block_q: the register, or the RAM's read register.
  logic             full_q, full_d, fresh_q;
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
      fresh_q <= 1'b0;
    end else begin
      full_q  <= full_d;
      fresh_q <= InRam && take;
    end
  end

  if (InRam) begin : g_ram
    // slot_q: the slot written last (the one read). Neither the RAM nor the read register
    // needs a reset: the block is read only once it is valid (the flip-flop part loads at
    // the take itself).
    localparam int RamBits = Width - FlopBits;
    (* ram_style = "block" *) logic [RamBits-1:0] slots [2];
    logic slot_q;
    always_ff @(posedge clk_i) begin
      if (!rst_ni) slot_q <= 1'b0;
      else if (take) slot_q <= !slot_q;
    end
    always_ff @(posedge clk_i) begin
      if (take) slots[!slot_q] <= in_block_i[RamBits-1:0];
      block_q[RamBits-1:0] <= slots[slot_q];
      if (take) block_q[Width-1:RamBits] <= in_block_i[Width-1:RamBits];
    end
  end else begin : g_register
    always_ff @(posedge clk_i) begin
      if (!rst_ni) block_q <= '0;
      else if (take) block_q <= in_block_i;
    end
  end

  assign in_ready_o  = !full_q;
  assign out_valid_o = full_q && !fresh_q;
  assign out_block_o = block_q;

endmodule
