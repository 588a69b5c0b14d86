// Formal harness of the line DDA: rtl/dda_circle.sv playing lines (line_i; its arcs are
// dda_circle_props.sv's).
//
// What is proven, for every block at width W (docs/verification.md, "Formal proofs"):
// - ap_pulses_*: in every clock after a block's last iteration (done_o), the step pulses
//   of each axis since its load number exactly |dx|, |dy|;
// - ap_step_*: a step pulse shows only in the clock after an iteration edge (one step per
//   axis per iteration, none in idle clocks; so at most one per axis per clock);
// - ap_dir_*: dir is the sign of the loaded increment and holds for the whole block
//   (it changes only at a load edge).
// Environment (what interp_top guarantees): reset in the first clock; a block loads only
// when the previous one has no iterations left; k = bit length of max(|dx|, |dy|); strobes
// arrive at any time. The harness keeps the loaded block and counts the pulses.
// Induction: the ai_* invariants tie the integrators to the pulse count (pulses * 2^k + acc
// = 2^(k-1) + j |d| after j iterations) and the pulse counters to the pulses left (so the
// counters never hold a pulse back); they read internal registers through formal-tap
// lines (scripts/formal.sh) and are left out of a mutant's BMC (FORMAL_PROPERTIES_ONLY), so a
// mutant fails on the property itself.
module dda_line_props #(
  parameter int W = 4
) (
  input logic         clk_i,
  input logic         rst_ni,
  input logic         load_i,
  input logic [W-1:0] dx_i,
  input logic         dx_neg_i,
  input logic [W-1:0] dy_i,
  input logic         dy_neg_i,
  input logic         strobe_i
);

  localparam int KWidth = $clog2(W + 1);
  localparam int CWidth = W + 1;        // pulse counts, 2^k and the iterations left
  localparam int PWidth = 2 * W + 4;    // products in the invariant

  logic [KWidth-1:0] k;
  logic carry_x, carry_y, step_x, step_y, dir_x, dir_y, rem_zero;  // rem_zero: done_o

  // k of the loading block: bit length of (|dx| | |dy|), as the decoder computes it.
  always_comb begin
    k = '0;
    for (int b = 0; b < W; b++) if (dx_i[b] || dy_i[b]) k = KWidth'(b + 1);
  end

  // Wired as interp_top wires a line: the arc-only inputs are not used.
  dda_circle #(.IncWidth(W), .KWidth(KWidth)) u_dut (
    .clk_i, .rst_ni, .load_i, .line_i(1'b1), .k_i(k), .x_i({W{1'b0}}), .y_i({W{1'b0}}),
    .cnt_x_i(dx_i), .cnt_y_i(dy_i), .grow_x_i(1'b0), .grow_y_i(1'b0),
    .dir_x_i(!dx_neg_i), .dir_y_i(!dy_neg_i), .strobe_i,
    .carry_x_o(carry_x), .carry_y_o(carry_y),
    .step_x_o(step_x), .dir_x_o(dir_x), .step_y_o(step_y), .dir_y_o(dir_y),
    .done_o(rem_zero)
  );

  // Model state: f_init is the first clock (reset); f_blk_q a block was loaded; the loaded
  // block; pulses since its load; f_iter_q the last edge was an iteration.
  logic              f_init = 1'b1;
  logic              f_blk_q, f_iter_q, f_neg_x_q, f_neg_y_q;
  logic [W-1:0]      f_inc_x_q, f_inc_y_q;
  logic [KWidth-1:0] f_k_q;
  logic [CWidth-1:0] f_steps_x_q, f_steps_y_q;

  always_ff @(posedge clk_i) begin
    f_init <= 1'b0;
    if (!rst_ni) begin
      f_blk_q <= 1'b0;  f_iter_q <= 1'b0;
      f_neg_x_q <= 1'b0;  f_neg_y_q <= 1'b0;  f_inc_x_q <= '0;  f_inc_y_q <= '0;  f_k_q <= '0;
      f_steps_x_q <= '0;  f_steps_y_q <= '0;
    end else begin
      f_iter_q <= !load_i && strobe_i && !rem_zero;
      if (load_i) begin
        f_blk_q <= 1'b1;
        f_neg_x_q <= dx_neg_i;  f_neg_y_q <= dy_neg_i;
        f_inc_x_q <= dx_i;      f_inc_y_q <= dy_i;
        f_k_q <= k;
        f_steps_x_q <= '0;      f_steps_y_q <= '0;
      end else begin
        f_steps_x_q <= f_steps_x_q + CWidth'(step_x);
        f_steps_y_q <= f_steps_y_q + CWidth'(step_y);
      end
    end
  end

  always_comb begin
    if (f_init) assume (!rst_ni);
    if (load_i) assume (rem_zero);
  end

  always_comb begin
    if (!f_init) begin
      if (f_blk_q && rem_zero) begin
        ap_pulses_x: assert (f_steps_x_q + CWidth'(step_x) == CWidth'(f_inc_x_q));
        ap_pulses_y: assert (f_steps_y_q + CWidth'(step_y) == CWidth'(f_inc_y_q));
      end
      if (step_x) ap_step_x: assert (f_iter_q);
      if (step_y) ap_step_y: assert (f_iter_q);
      if (f_blk_q) begin
        ap_dir_x: assert (dir_x == !f_neg_x_q);
        ap_dir_y: assert (dir_y == !f_neg_y_q);
      end
    end
  end

  // Internal registers for the invariants (driven by scripts/formal.sh).
  // A line's |dx| is in the Y magnitude register (the X integrator adds it), |dy| in X's.
  // formal-tap: tap_kpow = u_dut.kpow_q
  // formal-tap: tap_rem = u_dut.rem_q
  // formal-tap: tap_line = u_dut.line_q
  // formal-tap: tap_acc_x = u_dut.acc_x
  // formal-tap: tap_acc_y = u_dut.acc_y
  // formal-tap: tap_inc_x = u_dut.mag_y
  // formal-tap: tap_inc_y = u_dut.mag_x
  // formal-tap: tap_cnt_x = u_dut.cnt_x
  // formal-tap: tap_cnt_y = u_dut.cnt_y
  logic [W:0]   tap_kpow, tap_rem;
  logic         tap_line;
  logic [W-1:0] tap_acc_x, tap_acc_y, tap_inc_x, tap_inc_y, tap_cnt_x, tap_cnt_y;

`ifndef FORMAL_PROPERTIES_ONLY
  logic [W:0]   f_kpow, f_done;
  assign f_kpow = (W + 1)'(1) << f_k_q;
  assign f_done = tap_kpow - tap_rem;  // iterations done

  always_comb begin
    if (!f_init) begin
      if (!f_blk_q)
        ai_idle: assert (tap_rem == '0 && tap_cnt_x == '0 && tap_cnt_y == '0 && !step_x && !step_y);
      if (f_blk_q) begin
        ai_line: assert (tap_line);
        ai_kpow: assert (tap_kpow == f_kpow);
        ai_rem: assert (tap_rem <= tap_kpow);
        ai_inc_x: assert (tap_inc_x == f_inc_x_q && (W + 1)'(f_inc_x_q) < f_kpow);
        ai_inc_y: assert (tap_inc_y == f_inc_y_q && (W + 1)'(f_inc_y_q) < f_kpow);
        ai_acc_x: assert ((W + 1)'(tap_acc_x) < f_kpow);
        ai_acc_y: assert ((W + 1)'(tap_acc_y) < f_kpow);
        // The pulse counters hold the pulses still to come.
        ai_cnt_x: assert (CWidth'(tap_cnt_x) + f_steps_x_q + CWidth'(step_x) == CWidth'(f_inc_x_q));
        ai_cnt_y: assert (CWidth'(tap_cnt_y) + f_steps_y_q + CWidth'(step_y) == CWidth'(f_inc_y_q));
        // pulses * 2^k + acc = 2^(k-1) + j |d| after j iterations.
        ai_sum_x: assert (PWidth'(f_steps_x_q + CWidth'(step_x)) * PWidth'(f_kpow)
                          + PWidth'(tap_acc_x)
                          == PWidth'(f_kpow >> 1) + PWidth'(f_done) * PWidth'(f_inc_x_q));
        ai_sum_y: assert (PWidth'(f_steps_y_q + CWidth'(step_y)) * PWidth'(f_kpow)
                          + PWidth'(tap_acc_y)
                          == PWidth'(f_kpow >> 1) + PWidth'(f_done) * PWidth'(f_inc_y_q));
      end
    end
  end
`endif

  // Reachability: a block of the longest kind ends with pulses on both axes.
  always_comb begin
    if (!f_init) begin
      cp_block_ends: cover (f_blk_q && rem_zero && f_k_q == KWidth'(W) && f_steps_x_q > 1
                            && f_steps_y_q > 1 && !f_neg_x_q && f_neg_y_q);
    end
  end

endmodule
