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
//      read, so no edge reads and writes one address) and a registered read, every clock,
//      of the slot last written, or while hold_i of the slot popped last: the bit-serial
//      player (dda_serial.sv) reads a block's words from here in its first pass, while
//      the next block can already be taken into the other slot. The top FlopBits bits
//      stay in flip-flops beside it: interp_top puts N there, which a board leaves unused,
//      so synthesis removes N's logic (it cannot see through a RAM which of its bits are
//      read).
// The popped block's low PlayBits bits (interp_top puts S there, which the feed generator
// adds every clock while the block plays) are shown on a second output, out_play_o: a
// register loaded at the pop, or with InRam a second two-slot RAM written with the first
// and read at the popped block's slot, so that S needs no flip-flops on the board either.
// Timing: in_ready_o = empty (a register), so a block is taken at an edge where the
// buffer is empty, never in the edge that empties it; pop_i empties it at that edge.
// out_valid_o: the block can be read (and popped): from the edge after the take with the
// register; with the RAM once the registered read shows its slot, one edge after the take
// or after hold_i falls. out_play_o: from the edge after a pop until the next pop.
// Golden twin: the section "Block buffer" of GoldenInterp::tick()
// (sc_model/golden/interp_top.h), whose next_readable() is when the RAM's read shows the block.
module block_buffer #(
  parameter int Width    = 8,
  parameter bit InRam    = 1'b0,
  parameter int FlopBits = 1,   // with InRam: 1 .. Width - 1
  parameter int PlayBits = 1    // 1 .. Width
) (
  input  logic             clk_i,
  input  logic             rst_ni,
  input  logic             in_valid_i,
  output logic             in_ready_o,
  input  logic [Width-1:0] in_block_i,
  input  logic             pop_i,
  input  logic             hold_i,     // with InRam: show the popped block's slot
  output logic             out_valid_o,
  output logic [Width-1:0] out_block_o,
  // The low PlayBits bits of the block popped last (interp_top: its S).
  output logic [PlayBits-1:0] out_play_o
);

  // full_q: a block is held. block_q: the register, or the RAM's read register; shown: the
  // held block is what block_q shows (always with the register).
  logic             full_q, full_d, shown;
  logic [Width-1:0] block_q;
  logic [PlayBits-1:0] play_q;
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
    if (!rst_ni) full_q <= 1'b0;
    else         full_q <= full_d;
  end

  if (InRam) begin : g_ram
    // slot_q: the slot written last. read_slot: the slot read at this edge, the popped
    // block's while hold_i (the held block, if any, is then in the other one); shown_q:
    // the slot block_q holds. Neither the RAM nor the read register needs a reset: a block
    // is read only once it is shown (the flip-flop part loads at the take itself).
    localparam int RamBits = Width - FlopBits;
    (* ram_style = "block" *) logic [RamBits-1:0] slots [2];
    logic slot_q, shown_q, read_slot;
    assign read_slot = slot_q ^ (hold_i && full_q);
    always_ff @(posedge clk_i) begin
      if (!rst_ni) begin
        slot_q  <= 1'b0;
        shown_q <= 1'b0;
      end else begin
        if (take) slot_q <= !slot_q;
        shown_q <= read_slot;
      end
    end
    always_ff @(posedge clk_i) begin
      if (take) slots[!slot_q] <= in_block_i[RamBits-1:0];
      block_q[RamBits-1:0] <= slots[read_slot];
      if (take) block_q[Width-1:RamBits] <= in_block_i[Width-1:RamBits];
    end
    assign shown = !hold_i && shown_q == slot_q;
    // The play RAM: the same writes; read at the slot popped last (popped_q), or at a pop
    // at the popped block's, slot_q (a popped block is the one written last), so play_q
    // shows it from the edge after the pop. Its reads never meet a write either: a take
    // writes the slot that is not the popped block's.
    (* ram_style = "block", no_rw_check *) logic [PlayBits-1:0] plays [2];
    logic popped_q, play_slot;
    assign play_slot = pop_i ? slot_q : popped_q;
    always_ff @(posedge clk_i) begin
      if (!rst_ni) popped_q <= 1'b0;
      else         popped_q <= play_slot;
    end
    always_ff @(posedge clk_i) begin
      if (take) plays[!slot_q] <= in_block_i[PlayBits-1:0];
      play_q <= plays[play_slot];
    end
  end else begin : g_register
    always_ff @(posedge clk_i) begin
      if (!rst_ni) block_q <= '0;
      else if (take) block_q <= in_block_i;
    end
    always_ff @(posedge clk_i) begin
      if (!rst_ni) play_q <= '0;
      else if (pop_i) play_q <= block_q[PlayBits-1:0];
    end
    assign shown = 1'b1;
    /* verilator lint_off UNUSEDSIGNAL */
    logic unused_hold;
    /* verilator lint_on UNUSEDSIGNAL */
    assign unused_hold = hold_i;  // no RAM, no slot to show
  end

  assign in_ready_o  = !full_q;
  assign out_valid_o = full_q && shown;
  assign out_block_o = block_q;
  assign out_play_o  = play_q;

`ifndef SYNTHESIS
  // Checked at every edge of every verilated run (Verilator --assert) and in every formal
  // proof that reads this module (yosys -formal reads it; synthesis does not): only a
  // block that can be read is popped (with the RAM, a pop before its read shows the slot
  // would play the other slot's words).
  always_ff @(posedge clk_i) begin
    if (rst_ni) begin
      a_pop_readable: assert (!pop_i || out_valid_o);
    end
  end
`endif

endmodule
