// Formal harness of the tape decoder (rtl/tape_decoder.sv with arc_prepare.sv): its two
// handshakes (docs/interpolator.md 3.1 and 3.3).
//
// What is proven (BMC from reset, any frame stream, any reader and buffer timing):
// - ap_held_stable: a block the decoder offers (blk_valid_o) stays offered and unchanged,
//   every field, until the buffer takes it (blk_ready_i);
// - ap_ready_bounded (liveness in bounded-response form): frame_ready_o is never low for
//   more than K consecutive clocks unless the decoder is in error or holds a block. K =
//   max(D, (5W + 4)(2W + 4)) + 2 covers an arc's preparation (its dry run, D = 2^(W+1) >
//   N clocks, or at most 2W 2^(W+1) + W with BitSerial (2P N), and the bit-serial radius check,
//   docs/interpolator.md 3.5) and the clocks around it. So a byte stream ends in a played program, a held block, waiting for
//   frames, or an error, and nothing else stalls the reader;
// - ap_line_ready_bounded: while the block's motion is no arc (so no arc is prepared: a
//   line, a G00, or a still block, which shows as a G00), the bound is K_line = W + 4: a
//   line's addition of F, its k doublings and the clocks around them; with BitSerial at
//   least NumWidth + 1, a digit's x10 + d pass and the clock after it.
// Environment: reset in the first clock, tape_end_i stays high once high and no frame
// comes after it. Why BMC: k-induction would need invariants of the parser's and the arc
// preparation's internals, which change whenever their area is worked on. The CI depth (16 clocks)
// covers reading a line block and holding it (ap_held_stable); the stall bounds need more
// clocks, so they are checked by --deep (24 clocks: a short program and a line's K_line
// clocks beyond). An arc's K (114 clocks at W = 2) lies beyond that depth, so
// ap_ready_bounded holds there only as far as the depth reaches; an arc block needs about
// 15 clocks to be read, and the cover shows its preparation starts.
module tape_decoder_props #(
  parameter int W  = 2,
  parameter int FW = 2,
  parameter int NW = 2,
  parameter int OW = 5,
  parameter bit BitSerial = 1'b0
) (
  input logic       clk_i,
  input logic       rst_ni,
  input logic [7:0] frame_i,
  input logic       frame_valid_i,
  input logic       tape_end_i,
  input logic       blk_ready_i,
  input logic [4:0] rapid_step_i   // any static rapid step (ModulusWidth 5)
);

  localparam int KWidth = $clog2(W + 1);
  localparam int SW = FW + W + 1;
  localparam int Check = (5 * W + 4) * (2 * W + 4);  // ArcRadiusCheck::clocks
  localparam int Dry = BitSerial ? 2 * W * (1 << (W + 1)) + W : 1 << (W + 1);
  localparam int K = (Dry > Check ? Dry : Check) + 2;
  localparam int NumWidth = (W > FW ? W : FW) > (NW > 7 ? NW : 7) ? (W > FW ? W : FW)
                                                                   : (NW > 7 ? NW : 7);
  localparam int KDigit = BitSerial ? NumWidth + 1 : 0;
  localparam int KLine = W + 4 > KDigit ? W + 4 : KDigit;
  localparam int LowWidth = $clog2(K + 2);
  // The decoded block (`INTERP_BLOCK_T, sw/host/tape/block_record.def), with the names of
  // the widths it reads.
  localparam int IncWidth = W, SeqWidth = NW, StepWidth = SW, IterWidth = W + 1;
  `INTERP_BLOCK_T

  logic              frame_ready, blk_valid;
  logic              end_blk, tape_ended, err;
  logic [NW-1:0]     err_block;
  logic [interp_pkg::ErrCodeWidth-1:0] err_code;
  logic [OW-1:0]     err_offset;
  block_t            block;

  tape_decoder #(
    .IncWidth(W), .FracDigits(0), .FeedWidth(FW), .FeedFracDigits(0), .SeqWidth(NW),
    .OffsetWidth(OW), .ModulusWidth(5), .BitSerial(BitSerial)
  ) u_dut (
    .clk_i, .rst_ni, .rapid_step_i, .frame_i, .frame_valid_i, .tape_end_i, .frame_ready_o(frame_ready),
    .blk_valid_o(blk_valid), .blk_ready_i, .blk_o(block),
    .end_o(end_blk), .tape_ended_o(tape_ended), .err_o(err),
    .err_code_o(err_code), .err_block_o(err_block), .err_offset_o(err_offset)
  );

  // Model: clocks frame_ready has been low (saturating), the same while the block's motion
  // is no arc, the tape end seen.
  logic                f_init = 1'b1;
  logic                f_tape_end_q;
  logic [LowWidth-1:0] f_low_q, f_low_line_q;

  always_ff @(posedge clk_i) begin
    f_init <= 1'b0;
    f_tape_end_q <= tape_end_i && rst_ni;
    if (!rst_ni || frame_ready || err || blk_valid) f_low_q <= '0;
    else if (f_low_q != '1) f_low_q <= f_low_q + 1'b1;
    if (!rst_ni || frame_ready || err || blk_valid || interp_pkg::motion_is_arc(block.motion))
      f_low_line_q <= '0;
    else if (f_low_line_q != '1) f_low_line_q <= f_low_line_q + 1'b1;
  end

  // The rapid step is static configuration.
  logic [4:0] f_rapid_q;
  always_ff @(posedge clk_i) f_rapid_q <= rapid_step_i;

  always_comb begin
    assume (rst_ni == !f_init);
    if (!f_init) assume (rapid_step_i == f_rapid_q);
    if (f_tape_end_q) assume (tape_end_i);
    if (tape_end_i) assume (!frame_valid_i);
  end

  always_comb begin
    if (!f_init) begin
      ap_ready_bounded: assert (f_low_q <= LowWidth'(K));
      ap_line_ready_bounded: assert (f_low_line_q <= LowWidth'(KLine));
    end
  end

  logic f_past_valid = 1'b0;
  always_ff @(posedge clk_i) begin
    f_past_valid <= 1'b1;
    if (f_past_valid && $past(rst_ni) && $past(blk_valid && !blk_ready_i)) begin
      ap_held_stable: assert (blk_valid && $stable(block));
    end
  end

  // Reachability: a block is taken by the buffer; the reader is held off while an arc is
  // prepared (frame_ready low, no error, no block held: only in ARC).
  always_comb begin
    if (!f_init) begin
      cp_block_taken: cover (blk_valid && blk_ready_i);
      cp_arc_holds_reader: cover (f_low_q == LowWidth'(3));
    end
  end

endmodule
