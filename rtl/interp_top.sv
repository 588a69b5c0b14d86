// Interpolator top: plays a punched tape of line blocks into step/dir pulses.
//
// What: tape_decoder -> block_buffer ("next" block) -> player (feed_generator + dda_line)
// -> position counters, plus the machine status. Ports and parameters are the contract
// of docs/architecture.md; the microarchitecture and the clock-by-clock timing are in
// docs/interpolator.md, which the golden model (sc_model/golden/) follows too.
// Timing: every output is a register or a function of registers (Moore). A block loads at
// an edge where the buffer holds one and the player is idle or in the finishing clock of
// the previous block, so blocks follow without gap clocks when the reader keeps up. An
// error found while decoding is raised only when no good block is left to play.
module interp_top #(
  // Increment register width W: |dx|, |dy|, |i|, |j| of a block <= 2^IncWidth - 1 BLU.
  parameter int IncWidth       = 16,
  // Fraction digits of X, Y, I, J on tape: BLU = 10^-FracDigits mm.
  parameter int FracDigits     = 3,
  // F register (units of 10^-FeedFracDigits 1/min) and its fraction digits on tape.
  parameter int FeedWidth      = 32,
  parameter int FeedFracDigits = 3,
  // Signed position counters, BLU.
  parameter int PosWidth       = 32,
  // N (block sequence number).
  parameter int SeqWidth       = 20,
  // Frame offset counter (error reports).
  parameter int OffsetWidth    = 32,
  // Width of feed_modulus_i.
  parameter int ModulusWidth   = 48
) (
  input  logic                    clk_i,
  input  logic                    rst_ni,
  // Static configuration: 60 * f_clk * 10^FeedFracDigits.
  input  logic [ModulusWidth-1:0] feed_modulus_i,
  // Tape reader.
  input  logic [7:0]              frame_i,
  input  logic                    frame_valid_i,
  input  logic                    tape_end_i,
  output logic                    frame_ready_o,
  // Axes.
  output logic                    step_x_o,
  output logic                    dir_x_o,
  output logic                    step_y_o,
  output logic                    dir_y_o,
  output logic [PosWidth-1:0]     pos_x_o,
  output logic [PosWidth-1:0]     pos_y_o,
  // Status.
  output logic [SeqWidth-1:0]     block_n_o,
  output logic                    busy_o,
  output logic                    done_o,
  output logic                    error_o,
  output logic [3:0]              error_code_o,
  output logic [SeqWidth-1:0]     error_block_o,
  output logic [OffsetWidth-1:0]  error_offset_o,
  output logic                    feed_saturated_o
);

  localparam int KWidth = $clog2(IncWidth + 1);
  // A decoded block as the buffer stores it: N, motion, dx, dy, i, j (sign + magnitude), F,
  // and the DDA's k.
  localparam int BlockWidth = SeqWidth + 2 + 4 * (IncWidth + 1) + FeedWidth + KWidth;

  // Decoder -> buffer.
  logic                   dec_valid, buf_ready;
  logic [SeqWidth-1:0]    dec_n;
  logic [1:0]             dec_motion;
  logic [IncWidth-1:0]    dec_dx, dec_dy, dec_i, dec_j;
  logic                   dec_dx_neg, dec_dy_neg, dec_i_neg, dec_j_neg;
  logic [FeedWidth-1:0]   dec_feed;
  logic [KWidth-1:0]      dec_k;
  logic                   dec_end, dec_tape_ended, dec_err;
  logic [3:0]             dec_err_code;
  logic [SeqWidth-1:0]    dec_err_block;
  logic [OffsetWidth-1:0] dec_err_offset;

  // Buffer -> player.
  logic                   next_valid;
  logic [BlockWidth-1:0]  next_block;
  logic [SeqWidth-1:0]    next_n;
  logic [IncWidth-1:0]    next_dx, next_dy;
  logic                   next_dx_neg, next_dy_neg;
  logic [FeedWidth-1:0]   next_feed;
  logic [KWidth-1:0]      next_k;
  // Motion, I and J travel with the block for circle mode (next issue); lines ignore them.
  /* verilator lint_off UNUSEDSIGNAL */
  logic [1:0]             next_motion;
  logic [IncWidth-1:0]    next_i, next_j;
  logic                   next_i_neg, next_j_neg;
  /* verilator lint_on UNUSEDSIGNAL */

  // Player.
  logic              load, strobe, rem_zero, saturated, carry_x, carry_y;

  // busy_q: a block is loaded and not finished. block_n_q: its N (the last one when idle).
  // done_q / error_q: the machine has stopped at the end of the program / on a tape error.
  logic                busy_q, busy_d, done_q, done_d, error_q, error_d;
  logic [SeqWidth-1:0] block_n_q, block_n_d;

  tape_decoder #(
    .IncWidth(IncWidth), .FracDigits(FracDigits), .FeedWidth(FeedWidth),
    .FeedFracDigits(FeedFracDigits), .SeqWidth(SeqWidth), .OffsetWidth(OffsetWidth)
  ) u_decoder (
    .clk_i, .rst_ni,
    .frame_i, .frame_valid_i, .tape_end_i, .frame_ready_o,
    .blk_valid_o(dec_valid), .blk_ready_i(buf_ready),
    .blk_n_o(dec_n), .blk_motion_o(dec_motion),
    .blk_dx_o(dec_dx), .blk_dx_neg_o(dec_dx_neg), .blk_dy_o(dec_dy), .blk_dy_neg_o(dec_dy_neg),
    .blk_i_o(dec_i), .blk_i_neg_o(dec_i_neg), .blk_j_o(dec_j), .blk_j_neg_o(dec_j_neg),
    .blk_feed_o(dec_feed), .blk_k_o(dec_k),
    .end_o(dec_end), .tape_ended_o(dec_tape_ended), .err_o(dec_err), .err_code_o(dec_err_code),
    .err_block_o(dec_err_block), .err_offset_o(dec_err_offset)
  );

  block_buffer #(.Width(BlockWidth)) u_buffer (
    .clk_i, .rst_ni,
    .in_valid_i(dec_valid), .in_ready_o(buf_ready),
    .in_block_i({dec_n, dec_motion, dec_dx_neg, dec_dx, dec_dy_neg, dec_dy,
                 dec_i_neg, dec_i, dec_j_neg, dec_j, dec_feed, dec_k}),
    .pop_i(load),
    .out_valid_o(next_valid), .out_block_o(next_block)
  );

  assign {next_n, next_motion, next_dx_neg, next_dx, next_dy_neg, next_dy,
          next_i_neg, next_i, next_j_neg, next_j, next_feed, next_k} = next_block;

  // A block loads when one waits and the player is idle or finishing the previous block.
  assign load = next_valid && (!busy_q || rem_zero);

  feed_generator #(
    .FeedWidth(FeedWidth), .IncWidth(IncWidth), .ModulusWidth(ModulusWidth), .KWidth(KWidth)
  ) u_feed (
    .clk_i, .rst_ni,
    .load_i(load), .feed_i(next_feed), .k_i(next_k),
    .run_i(busy_q && !rem_zero), .modulus_i(feed_modulus_i),
    .strobe_o(strobe), .saturated_o(saturated)
  );

  dda_line #(.IncWidth(IncWidth), .KWidth(KWidth)) u_dda (
    .clk_i, .rst_ni,
    .load_i(load), .k_i(next_k),
    .dx_i(next_dx), .dx_neg_i(next_dx_neg), .dy_i(next_dy), .dy_neg_i(next_dy_neg),
    .strobe_i(strobe),
    .carry_x_o(carry_x), .carry_y_o(carry_y),
    .step_x_o, .dir_x_o, .step_y_o, .dir_y_o,
    .rem_zero_o(rem_zero)
  );

  position_counter #(.PosWidth(PosWidth)) u_pos_x (
    .clk_i, .rst_ni, .count_i(carry_x), .up_i(dir_x_o), .pos_o(pos_x_o)
  );

  position_counter #(.PosWidth(PosWidth)) u_pos_y (
    .clk_i, .rst_ni, .count_i(carry_y), .up_i(dir_y_o), .pos_o(pos_y_o)
  );

  // Status. The decoder's error and end wait until nothing is left to play.
  always_comb begin
    busy_d    = busy_q;
    block_n_d = block_n_q;
    if (load) begin
      busy_d    = 1'b1;
      block_n_d = next_n;
    end else if (busy_q && rem_zero) begin
      busy_d = 1'b0;  // finished with no next block: a gap (or the end)
    end
    error_d = error_q | (dec_err & !busy_q & !next_valid);
    done_d  = done_q | (dec_end & dec_tape_ended & !busy_q & !next_valid);
  end

  always_ff @(posedge clk_i) begin
    if (!rst_ni) begin
      busy_q    <= 1'b0;
      block_n_q <= '0;
      done_q    <= 1'b0;
      error_q   <= 1'b0;
    end else begin
      busy_q    <= busy_d;
      block_n_q <= block_n_d;
      done_q    <= done_d;
      error_q   <= error_d;
    end
  end

  assign block_n_o        = block_n_q;
  assign busy_o           = busy_q;
  assign done_o           = done_q;
  assign error_o          = error_q;
  assign error_code_o     = error_q ? dec_err_code : '0;
  assign error_block_o    = error_q ? dec_err_block : '0;
  assign error_offset_o   = error_q ? dec_err_offset : '0;
  assign feed_saturated_o = busy_q & saturated;

endmodule
