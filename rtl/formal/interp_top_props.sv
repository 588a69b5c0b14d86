// Formal harness of the whole interpolator (rtl/interp_top.sv) at small widths: the
// machine-level promises (docs/interpolator.md sections 5.4 and 6).
//
// What is proven (BMC from reset, any frame stream, any reader timing):
// - ap_step_busy: no step pulse while idle (every pulse belongs to a playing block);
// - ap_stopped: no step and no block playing once done or in error; never both;
// - ap_error_sticky, ap_done_sticky: error and done never fall, and the error report
//   (code, block, offset) does not change once shown;
// - ap_bad_block: after the decoder has found a tape error no block enters the buffer, so
//   no pulse comes from the bad block (the good blocks before it finish first);
// - ap_done_end: done only after an M02/M30 word was read (outside comments, after the
//   leader), with every block the decoder handed over loaded and finished;
// - ap_pos_*: the position counters always equal the integrated pulses (+1 or -1 by dir,
//   counted at the edge of the pulse), also after a stop;
// - the stops (estop_i, limit_x_i, limit_y_i, free inputs): ap_stop_quiet, no step pulse
//   after the clock that follows the edge that latched a stop (the pulse of that edge is
//   the last), in both archs; ap_stop_raised, a stop input seen while the program runs
//   raises the error with the input's code at that edge (E-stop before X before Y);
//   ap_stop_named, a stop's code only after its input was seen.
// The harness reads the taken frames with its own small recogniser of M words, counts the
// blocks handed over and loaded (formal-tap lines: interp_top's decoder/buffer handshake and
// load), and integrates the pulses. Environment: reset in the first clock, a static modulus
// (>= 1), tape_end_i stays high once high and no frame comes after it.
// Why BMC: the decoder and arc preparation have too much unreachable state for k-induction
// without invariants of their internals, which change whenever their area is worked on; the depth (22)
// covers a whole program of one block played to done at these widths (the cover reaches it
// at step 21).
module interp_top_props #(
  parameter int W  = 2,   // IncWidth
  parameter int FW = 2,   // FeedWidth
  parameter int MW = 3,   // ModulusWidth
  parameter int PW = 4,   // PosWidth
  parameter int NW = 2,   // SeqWidth
  parameter int OW = 5,   // OffsetWidth
  parameter bit BS = 1'b0, // BitSerial: 1 the serial arch (the boards'), 0 the parallel one
  // 1: cover motion on both axes and a program played to done (step 22 in the parallel
  // arch). The serial arch's iterations of 4 clocks put both beyond 26 steps, so its default
  // run covers a block playing and an error after it, and leaves them to --deep
  // (rtl/formal/proofs).
  parameter bit CoverMotion = 1'b1
) (
  input logic          clk_i,
  input logic          rst_ni,
  input logic [MW-1:0] feed_modulus_i,
  input logic [MW-1:0] rapid_step_i,
  input logic [7:0]    frame_i,
  input logic          frame_valid_i,
  input logic          tape_end_i,
  input logic          estop_i,
  input logic          limit_x_i,
  input logic          limit_y_i
);

  logic          frame_ready, step_x, dir_x, step_y, dir_y, busy, done, error, saturated;
  /* verilator lint_off UNUSEDSIGNAL */
  logic          tool, paused;  // the M words' outputs: interp_top's own assertions
  /* verilator lint_on UNUSEDSIGNAL */
  logic [PW-1:0] pos_x, pos_y;
  logic [NW-1:0] block_n, error_block;
  logic [interp_pkg::ErrCodeWidth-1:0] error_code;
  logic [OW-1:0] error_offset;

  interp_top #(
    .IncWidth(W), .FracDigits(0), .FeedWidth(FW), .FeedFracDigits(0), .PosWidth(PW),
    .SeqWidth(NW), .OffsetWidth(OW), .ModulusWidth(MW), .BitSerial(BS)
  ) u_dut (
    .clk_i, .rst_ni, .feed_modulus_i, .rapid_step_i, .accel_step_i(MW'(0)), .hold_i(1'b0), .start_i(1'b0),
    .feed_override_i(interp_pkg::OverrideOne), .rapid_override_i(interp_pkg::OverrideOne),
    .estop_i, .limit_x_i, .limit_y_i, .optional_stop_i(1'b0), .frame_i, .frame_valid_i,
    .tape_end_i,
    .frame_ready_o(frame_ready), .step_x_o(step_x), .dir_x_o(dir_x), .step_y_o(step_y),
    .dir_y_o(dir_y), .pos_x_o(pos_x), .pos_y_o(pos_y), .block_n_o(block_n), .busy_o(busy),
    .done_o(done), .error_o(error), .error_code_o(error_code), .error_block_o(error_block),
    .error_offset_o(error_offset), .feed_saturated_o(saturated), .tool_o(tool),
    .paused_o(paused)
  );

  // formal-tap: tap_dec_valid = u_dut.dec_valid
  // formal-tap: tap_buf_ready = u_dut.buf_ready
  // formal-tap: tap_dec_err = u_dut.dec_err
  // formal-tap: tap_load = u_dut.load
  logic tap_dec_valid, tap_buf_ready, tap_dec_err, tap_load;

  // Model: M-word recogniser over the taken frames (f_body_q after '%', f_comment_q inside
  // a comment, f_m_q reading an M number of value f_mval_q, f_end_q an M02/M30 was read);
  // blocks handed over and loaded (4 bits: a short BMC plays few); the decoder has erred;
  // integrated pulses.
  logic          f_init = 1'b1;
  logic          f_body_q, f_comment_q, f_m_q, f_end_q, f_dec_err_q, f_tape_end_q;
  logic [6:0]    f_mval_q;
  logic [3:0]    f_handed_q, f_loaded_q;
  logic [PW-1:0] f_int_x_q, f_int_y_q;
  logic [MW-1:0] f_modulus_q, f_rapid_q;
  logic [6:0]    ch;
  logic          take, digit;
  assign take  = frame_valid_i && frame_ready;
  assign ch    = frame_i[6:0];
  assign digit = ch >= 7'h30 && ch <= 7'h39;

  always_ff @(posedge clk_i) begin
    f_init <= 1'b0;
    f_modulus_q <= feed_modulus_i;
    f_rapid_q <= rapid_step_i;
    f_tape_end_q <= tape_end_i;
    if (!rst_ni) begin
      f_body_q <= 1'b0;  f_comment_q <= 1'b0;  f_m_q <= 1'b0;  f_end_q <= 1'b0;
      f_mval_q <= '0;  f_dec_err_q <= 1'b0;  f_handed_q <= '0;  f_loaded_q <= '0;
      f_int_x_q <= '0;  f_int_y_q <= '0;  f_tape_end_q <= 1'b0;
    end else begin
      if (take) begin
        if (!f_body_q) begin
          f_body_q <= ch == 7'h25;
        end else if (f_comment_q) begin
          f_comment_q <= ch != 7'h29;
        end else if (f_m_q && digit) begin
          f_mval_q <= f_mval_q > 7'd99 ? f_mval_q : f_mval_q * 7'd10 + 7'(ch - 7'h30);
        end else if (f_m_q && (ch == 7'h20 || ch == 7'h0d)) begin
          // CR and space are ignored inside a number
        end else begin
          if (f_m_q && (f_mval_q == 7'd2 || f_mval_q == 7'd30)) f_end_q <= 1'b1;
          f_m_q <= ch == 7'h4d;
          f_mval_q <= '0;
          f_comment_q <= ch == 7'h28;
        end
      end
      if (tap_dec_err) f_dec_err_q <= 1'b1;
      if (tap_dec_valid && tap_buf_ready) f_handed_q <= f_handed_q + 1'b1;
      if (tap_load) f_loaded_q <= f_loaded_q + 1'b1;
      if (step_x) f_int_x_q <= dir_x ? f_int_x_q + 1'b1 : f_int_x_q - 1'b1;
      if (step_y) f_int_y_q <= dir_y ? f_int_y_q + 1'b1 : f_int_y_q - 1'b1;
    end
  end

  always_comb begin
    assume (rst_ni == !f_init);
    if (!f_init) assume (feed_modulus_i == f_modulus_q && feed_modulus_i != '0 &&
                         rapid_step_i == f_rapid_q);
    if (f_tape_end_q) assume (tape_end_i);
    if (tape_end_i) assume (!frame_valid_i);
  end

  always_comb begin
    if (!f_init) begin
      if (step_x || step_y) ap_step_busy: assert (busy);
      if (done || (error && !f_stop_error)) ap_stopped: assert (!step_x && !step_y && !busy);
      ap_not_both: assert (!(done && error));
      if (f_dec_err_q) ap_bad_block: assert (!(tap_dec_valid && tap_buf_ready));
      if (done) ap_done_end: assert (f_end_q && f_handed_q == f_loaded_q && !busy);
      ap_pos_x: assert (pos_x == (step_x ? (dir_x ? f_int_x_q + 1'b1 : f_int_x_q - 1'b1) : f_int_x_q));
      ap_pos_y: assert (pos_y == (step_y ? (dir_y ? f_int_y_q + 1'b1 : f_int_y_q - 1'b1) : f_int_y_q));
    end
  end

  // The stops. f_stop_error: the error shown is a stop's. f_stop_age_q: edges since the one
  // that latched it (saturating); f_seen_q: the stop inputs seen high at an edge so far.
  logic       f_stop_error;
  logic [1:0] f_stop_age_q;
  logic [2:0] f_seen_q;
  assign f_stop_error = error && error_code >= interp_pkg::ErrEmergencyStop;
  always_ff @(posedge clk_i) begin
    if (!rst_ni) begin
      f_stop_age_q <= '0;
      f_seen_q     <= '0;
    end else begin
      if (f_stop_error && f_stop_age_q != '1) f_stop_age_q <= f_stop_age_q + 1'b1;
      f_seen_q <= f_seen_q | {limit_y_i, limit_x_i, estop_i};
    end
  end
  always_comb begin
    if (!f_init) begin
      if (f_stop_error && f_stop_age_q != '0) ap_stop_quiet: assert (!step_x && !step_y);
      if (error_code == interp_pkg::ErrEmergencyStop) ap_stop_named_e: assert (f_seen_q[0]);
      if (error_code == interp_pkg::ErrLimitX) ap_stop_named_x: assert (f_seen_q[1]);
      if (error_code == interp_pkg::ErrLimitY) ap_stop_named_y: assert (f_seen_q[2]);
    end
  end

  logic f_past_valid = 1'b0;
  always_ff @(posedge clk_i) begin
    f_past_valid <= 1'b1;
    if (f_past_valid && $past(rst_ni) && !$past(done) && !$past(error) &&
        ($past(estop_i) || $past(limit_x_i) || $past(limit_y_i)))
      ap_stop_raised: assert (error && error_code == ($past(estop_i) ? interp_pkg::ErrEmergencyStop
                                                     : $past(limit_x_i) ? interp_pkg::ErrLimitX
                                                     : interp_pkg::ErrLimitY));
    if (f_past_valid && $past(rst_ni)) begin
      if ($past(error)) ap_error_sticky: assert (error && $stable(error_code)
                                                 && $stable(error_block) && $stable(error_offset));
      if ($past(done)) ap_done_sticky: assert (done);
    end
  end

  // Reachability: a block plays; a tape error is reported after a block has played; and
  // (CoverMotion) a block moves both axes, a program whose block moved both axes is played
  // to done, and a stop comes after motion.
  always_comb begin
    if (!f_init) begin
      cp_playing: cover (busy && f_loaded_q != '0);
      cp_error_after_block: cover (error && f_loaded_q != '0);
    end
  end
  if (CoverMotion) begin : g_cover_motion
    always_comb begin
      if (!f_init) begin
        cp_moved_both: cover (pos_x != '0 && pos_y != '0);
        cp_done_after_motion: cover (done && pos_x != '0 && pos_y != '0);
        cp_stop_moved: cover (f_stop_error && (pos_x != '0 || pos_y != '0));
      end
    end
  end

endmodule
