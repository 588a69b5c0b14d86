// Formal harness of the bit-serial DDA (rtl/dda_serial.sv, the boards' player and dry run):
// a miter against the one-clock DDA (rtl/dda_circle.sv), lines and arcs at width W.
//
// What is proven: both DDAs load the same block at the same edge, a line (k = bit length of
// max(|dx|, |dy|), as the decoder computes it) or an arc that passes arc_geometry's checks
// (its k and growth; the end need not be on the circle). The serial DDA
// reads the block's words bit by bit in its first pass, as interp_top feeds them; the
// one-clock DDA iterates at the edge where the serial one starts an iteration (iterate_o).
// A strobe comes in every clock: the serial DDA starts an iteration at the first strobe
// while it is idle and ignores the others (a clock without an iteration changes no state of
// either DDA, so when the strobes come does not change the sequence). Then, at every
// iteration:
// - ap_pulses_x, ap_pulses_y: a pulse comes only within an iteration, at most one per axis
//   per iteration, and only where the one-clock DDA pulsed in the same iteration;
// - ap_all_x, ap_all_y: when the iteration ends, it has given every one of those pulses;
// - ap_done: when the iteration's last pass ends, done_o equals the one-clock DDA's done;
// - ap_dir: the directions are the one-clock DDA's.
// So the serial DDA plays every block with the same pulses, in the same order and in the
// same number of iterations as dda_circle.sv, whose own proofs (dda_line_props.sv,
// dda_circle_props.sv) show those pulses right; the serial one only takes 2P clocks for
// each. Bound: a block has fewer than 2^(W+1) iterations of 2P clocks (P = W rounded up to
// a power of two), so BMC to 2 + 2P * 2^(W+1) steps covers every block of width W to its
// end: at that width the proof is complete. The covers show a full quadrant arc and a
// line completing.
module dda_serial_props #(
  parameter int W = 2
) (
  input logic         clk_i,
  input logic         rst_ni,
  input logic         line_i,
  input logic [W-1:0] dx_i,
  input logic         dx_neg_i,
  input logic [W-1:0] dy_i,
  input logic         dy_neg_i,
  input logic [W-1:0] i_i,
  input logic         i_neg_i,
  input logic [W-1:0] j_i,
  input logic         j_neg_i,
  input logic         ccw_i
);

  localparam int KWidth = $clog2(W + 1);
  localparam int BitWidth = $clog2(W);
  localparam int Iteration = 2 << BitWidth;  // 2P clocks

  logic       f_init = 1'b1;
  logic [1:0] f_age_q;  // edges since reset, saturating at 2
  logic       load;
  assign load = f_age_q == 2'd1;

  // The block's k and growth: a line's from its increments, an arc's from the geometry.
  logic              grow_x, grow_y, geo_err, add_x, add_y, geo_shift, geo_done;
  logic [interp_pkg::ErrCodeWidth-1:0] geo_code;
  logic [KWidth-1:0] arc_k, line_k, k;
  arc_geometry #(.IncWidth(W), .KWidth(KWidth)) u_geometry (
    .clk_i, .rst_ni, .enable_i(1'b1), .shift_o(geo_shift), .done_o(geo_done),
    .dx_i, .dx_neg_i, .dy_i, .dy_neg_i, .i_i, .i_neg_i, .j_i, .j_neg_i, .ccw_i,
    .grow_x_o(grow_x), .grow_y_o(grow_y), .add_x_o(add_x), .add_y_o(add_y), .k_o(arc_k),
    .error_o(geo_err), .error_code_o(geo_code)
  );
  always_comb begin
    line_k = '0;
    for (int b = 0; b < W; b++) if (dx_i[b] || dy_i[b]) line_k = KWidth'(b + 1);
  end
  assign k = line_i ? line_k : arc_k;

  // The reference: the one-clock DDA, iterated when the serial one starts an iteration.
  logic iterate;
  logic c_carry_x, c_carry_y, c_step_x, c_step_y, c_dir_x, c_dir_y, c_done;
  dda_circle #(.IncWidth(W), .KWidth(KWidth)) u_ref (
    .clk_i, .rst_ni, .load_i(load), .line_i, .k_i(k), .x_i(i_i), .y_i(j_i),
    .cnt_x_i(dx_i), .cnt_y_i(dy_i), .grow_x_i(grow_x), .grow_y_i(grow_y),
    .dir_x_i(!dx_neg_i), .dir_y_i(!dy_neg_i), .strobe_i(iterate),
    .carry_x_o(c_carry_x), .carry_y_o(c_carry_y), .step_x_o(c_step_x), .dir_x_o(c_dir_x),
    .step_y_o(c_step_y), .dir_y_o(c_dir_y), .done_o(c_done)
  );

  // The serial DDA reads the loaded block's words, bit bit_o of each in its first pass.
  logic [W-1:0]        f_dx_q, f_dy_q, f_i_q, f_j_q;
  logic [BitWidth-1:0] bit_idx;
  logic                s_carry_x, s_carry_y, s_step_x, s_step_y, s_dir_x, s_dir_y, s_words, s_done;
  function automatic logic word_bit(input logic [W-1:0] word, input logic [BitWidth-1:0] i);
    word_bit = 32'(i) < W ? word[i] : 1'b0;
  endfunction
  dda_serial #(.IncWidth(W), .KWidth(KWidth)) u_dut (
    .clk_i, .rst_ni, .load_i(load), .line_i, .k_i(k),
    .x_bit_i(word_bit(f_i_q, bit_idx)), .y_bit_i(word_bit(f_j_q, bit_idx)),
    .cnt_x_bit_i(word_bit(f_dx_q, bit_idx)), .cnt_y_bit_i(word_bit(f_dy_q, bit_idx)),
    .bit_o(bit_idx), .grow_x_i(grow_x), .grow_y_i(grow_y),
    .dir_x_i(!dx_neg_i), .dir_y_i(!dy_neg_i), .strobe_i(1'b1), .mute_i(1'b0), .iterate_o(iterate),
    .carry_x_o(s_carry_x), .carry_y_o(s_carry_y), .step_x_o(s_step_x), .dir_x_o(s_dir_x),
    .step_y_o(s_step_y), .dir_y_o(s_dir_y), .words_o(s_words), .done_o(s_done)
  );

  // Model: the iteration running (f_run_q) and its clock (f_clock_q), the one-clock DDA's
  // pulses of it (f_ref_x_q, f_ref_y_q) and the serial pulses so far (f_got_x_q, ...);
  // f_ended_q: a serial iteration ended at the last edge.
  logic                f_loaded_q, f_run_q, f_ended_q;
  logic [$clog2(Iteration)-1:0] f_clock_q;
  logic                f_ref_x_q, f_ref_y_q, f_got_x_q, f_got_y_q;
  logic                last_clock;
  assign last_clock = f_run_q && f_clock_q == ($clog2(Iteration))'(Iteration - 1);

  always_ff @(posedge clk_i) begin
    f_init <= 1'b0;
    if (!rst_ni) begin
      f_age_q <= '0;
      f_loaded_q <= 1'b0;  f_run_q <= 1'b0;  f_ended_q <= 1'b0;  f_clock_q <= '0;
      {f_ref_x_q, f_ref_y_q, f_got_x_q, f_got_y_q} <= '0;
      {f_dx_q, f_dy_q, f_i_q, f_j_q} <= '0;
    end else begin
      if (f_age_q != 2'd2) f_age_q <= f_age_q + 1'b1;
      f_ended_q <= last_clock;
      if (load) begin
        f_loaded_q <= 1'b1;
        {f_dx_q, f_dy_q} <= {dx_i, dy_i};
        {f_i_q, f_j_q} <= line_i ? '0 : {i_i, j_i};
      end
      if (iterate) begin
        f_run_q <= 1'b1;
        f_clock_q <= 1;
        {f_ref_x_q, f_ref_y_q} <= {c_carry_x, c_carry_y};
        {f_got_x_q, f_got_y_q} <= {s_carry_x, s_carry_y};
      end else if (f_run_q) begin
        f_clock_q <= f_clock_q + 1'b1;
        f_got_x_q <= f_got_x_q | s_carry_x;
        f_got_y_q <= f_got_y_q | s_carry_y;
        if (last_clock) f_run_q <= 1'b0;
      end
    end
  end

  always_comb begin
    assume (rst_ni == !f_init);
    // An arc passes the geometry's checks (the same integers play any such arc in both
    // DDAs, so the end-on-circle rule, which needs squares, is not assumed: the proof
    // covers more arcs than the decoder hands over).
    if (load && !line_i) assume (!geo_err);
    // The words matter only at the load (the serial DDA reads the harness's copy).
    if (!load) assume ({line_i, dx_i, dx_neg_i, dy_i, dy_neg_i, i_i, i_neg_i, j_i, j_neg_i, ccw_i} == '0);
  end

  // This clock's iteration: the reference's pulses and the serial ones before this clock.
  logic in_iteration, ref_x, ref_y, got_x, got_y;
  assign in_iteration = iterate || f_run_q;
  assign {ref_x, ref_y} = iterate ? {c_carry_x, c_carry_y} : {f_ref_x_q, f_ref_y_q};
  assign {got_x, got_y} = iterate ? 2'b00 : {f_got_x_q, f_got_y_q};

  always_comb begin
    if (!f_init && f_loaded_q) begin
      // A pulse outside an iteration, a second one of an axis in one iteration, or one the
      // reference does not have.
      if (s_carry_x) ap_pulses_x: assert (in_iteration && ref_x && !got_x);
      if (s_carry_y) ap_pulses_y: assert (in_iteration && ref_y && !got_y);
      // The iteration ends with every pulse of the reference's.
      if (last_clock) begin
        ap_all_x: assert ((f_got_x_q | s_carry_x) == f_ref_x_q);
        ap_all_y: assert ((f_got_y_q | s_carry_y) == f_ref_y_q);
      end
      if (f_ended_q) ap_done: assert (s_done == c_done);
      ap_dir: assert (s_dir_x == c_dir_x && s_dir_y == c_dir_y);
    end
  end

  // Reachability: a full quadrant arc of the largest radius, and a line, played to the end.
  always_comb begin
    if (!f_init) begin
      cp_arc_completes: cover (f_loaded_q && f_ended_q && s_done && f_i_q == W'((1 << W) - 1)
                               && f_dx_q == W'((1 << W) - 1));
      cp_line_completes: cover (f_loaded_q && f_ended_q && s_done && f_dx_q == W'((1 << W) - 1)
                                && f_i_q == '0);
    end
  end

endmodule
