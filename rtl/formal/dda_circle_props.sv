// Formal harness of the circle DDA (rtl/dda_circle.sv) playing arcs, docs/circle-dda.md
// (lines on the same module: dda_line_props.sv).
//
// What is proven, for every quadrant arc the decoder accepts at width W (exhaustively: the
// arc's words are free, BMC covers the whole block):
// - ap_end_*: when the block is over (done_o) the pulses have moved the tool exactly to the
//   programmed end (X, Y);
// - ap_dir_*: every pulse moves the way the arc goes (dir = sign of X, Y);
// - ap_finishes: the block ends within 2^(k+1) iterations (N < 2^(k+1), so S = F N fits);
// - ap_radial: after every pulse the point is within 1 BLU of the circle through the start
//   about the centre, | |p| - R0 | <= 1, in integers (B - A - 1)^2 <= 4 A with A = R0^2,
//   B = |p|^2 (docs/circle-dda.md 2.2 and the bound of 3.2);
// - ap_step_*: a pulse shows only in the clock after an iteration edge.
// "Accepted" is the decoder's rule: arc_geometry.sv (zero radius, one quadrant, width) and
// the end-on-circle rule (B1 - A - 1)^2 <= 4 A, written here from docs/circle-dda.md 2.2
// (the RTL's bit-serial arc_radius_check.sv computes the same). The load inputs are wired as
// interp_top wires them. Environment: reset in the first clock, the arc loads at the next
// edge, then one strobe per clock: a clock without a strobe changes no iteration state (it
// only clears the step registers), so the sequence of points does not depend on when the
// strobes come. The harness integrates the pulses into a signed position about the centre.
// BMC to depth 2^(W+1) + 4 covers the whole block (N < 2^(W+1) is asserted); no induction
// (the radial bound is not inductive without the orbit).
module dda_circle_props #(
  parameter int W = 3
) (
  input logic         clk_i,
  input logic         rst_ni,
  input logic [W-1:0] dx_i,
  input logic         dx_neg_i,
  input logic [W-1:0] dy_i,
  input logic         dy_neg_i,
  input logic [W-1:0] i_i,
  input logic         i_neg_i,
  input logic [W-1:0] j_i,
  input logic         j_neg_i,
  input logic         ccw_i,
  // The radial band [lo, hi] of |p|^2 allowed about the start circle, chosen at the load
  // (constrained there to be exactly the squares within 1 BLU of R0: no multiplication is
  // needed in later clocks, which keeps the solver fast).
  input logic [2*W+5:0] band_lo_i,
  input logic [2*W+5:0] band_hi_i
);

  localparam int KWidth = $clog2(W + 1);
  localparam int SW = W + 3;          // signed coordinates about the centre
  localparam int QW = 2 * SW + 2;     // squares and their differences
  localparam int RW = 2 * QW;         // the square of a difference

  logic              f_init = 1'b1;
  logic [1:0]        f_age_q;         // edges since reset, saturating at 2
  logic              load, strobe;
  assign load   = f_age_q == 2'd1;
  assign strobe = f_age_q == 2'd2;

  // The arc's geometry and the decoder's checks.
  logic              grow_x, grow_y, geo_err, add_x, add_y, geo_shift, geo_done;
  logic [interp_pkg::ErrCodeWidth-1:0] geo_code;
  logic [KWidth-1:0] k;
  arc_geometry #(.IncWidth(W), .KWidth(KWidth)) u_geometry (
    .clk_i, .rst_ni, .enable_i(1'b1), .shift_o(geo_shift), .done_o(geo_done),
    .dx_i, .dx_neg_i, .dy_i, .dy_neg_i, .i_i, .i_neg_i, .j_i, .j_neg_i, .ccw_i,
    .grow_x_o(grow_x), .grow_y_o(grow_y), .add_x_o(add_x), .add_y_o(add_y), .k_o(k),
    .error_o(geo_err), .error_code_o(geo_code)
  );

  logic carry_x, carry_y, step_x, step_y, dir_x, dir_y, done;
  dda_circle #(.IncWidth(W), .KWidth(KWidth)) u_dut (
    .clk_i, .rst_ni, .load_i(load), .line_i(1'b0), .k_i(k), .x_i(i_i), .y_i(j_i),
    .cnt_x_i(dx_i), .cnt_y_i(dy_i), .grow_x_i(grow_x), .grow_y_i(grow_y),
    .dir_x_i(!dx_neg_i), .dir_y_i(!dy_neg_i), .strobe_i(strobe),
    .carry_x_o(carry_x), .carry_y_o(carry_y), .step_x_o(step_x), .dir_x_o(dir_x),
    .step_y_o(step_y), .dir_y_o(dir_y), .done_o(done)
  );

  // Signed words of the loading arc: start S = -(I, J) about the centre, end E = S + (X, Y).
  logic signed [SW-1:0] s_x0, s_y0, s_x1, s_y1;
  logic signed [QW-1:0] a_now, b_end;
  assign s_x0 = i_neg_i ? SW'(i_i) : -(SW'(i_i));
  assign s_y0 = j_neg_i ? SW'(j_i) : -(SW'(j_i));
  assign s_x1 = s_x0 + (dx_neg_i ? -(SW'(dx_i)) : SW'(dx_i));
  assign s_y1 = s_y0 + (dy_neg_i ? -(SW'(dy_i)) : SW'(dy_i));
  assign a_now = QW'(s_x0) * QW'(s_x0) + QW'(s_y0) * QW'(s_y0);
  assign b_end = QW'(s_x1) * QW'(s_x1) + QW'(s_y1) * QW'(s_y1);

  // |sqrt(b) - sqrt(a)| <= 1, a >= 1.
  function automatic logic on_circle(input logic signed [QW-1:0] a, input logic signed [QW-1:0] b);
    logic signed [RW-1:0] e;
    e = RW'(b) - RW'(a) - 1;
    on_circle = e * e <= 4 * RW'(a);
  endfunction

  // Model: the loaded arc (end, radial band, signs), the position from the pulses shown so
  // far (f_x_q, f_y_q: pulses of earlier clocks) and its |p|^2 (f_b_q, kept by adding
  // +-2x + 1 at a step), the iterations done and 2^k.
  logic                 f_loaded_q, f_iter_edge_q, f_neg_x_q, f_neg_y_q;
  logic signed [SW-1:0] f_x_q, f_y_q, f_x1_q, f_y1_q;
  logic signed [QW-1:0] f_lo_q, f_hi_q, f_b_q;
  logic [W+1:0]         f_iter_q, f_kpow_q;

  always_ff @(posedge clk_i) begin
    f_init <= 1'b0;
    if (!rst_ni) begin
      f_age_q <= '0;  f_loaded_q <= 1'b0;  f_iter_edge_q <= 1'b0;
      f_neg_x_q <= 1'b0;  f_neg_y_q <= 1'b0;
      f_x_q <= '0;  f_y_q <= '0;  f_x1_q <= '0;  f_y1_q <= '0;
      f_lo_q <= '0;  f_hi_q <= '0;  f_b_q <= '0;
      f_iter_q <= '0;  f_kpow_q <= '0;
    end else begin
      if (f_age_q != 2'd2) f_age_q <= f_age_q + 1'b1;
      f_iter_edge_q <= strobe && !done;
      if (load) begin
        f_loaded_q <= 1'b1;
        f_neg_x_q <= dx_neg_i;  f_neg_y_q <= dy_neg_i;
        f_x_q <= s_x0;  f_y_q <= s_y0;  f_x1_q <= s_x1;  f_y1_q <= s_y1;
        f_lo_q <= QW'(band_lo_i);  f_hi_q <= QW'(band_hi_i);  f_b_q <= a_now;
        f_kpow_q <= (W + 2)'(1) << k;
      end else begin
        if (step_x) f_x_q <= dir_x ? f_x_q + 1'b1 : f_x_q - 1'b1;
        if (step_y) f_y_q <= dir_y ? f_y_q + 1'b1 : f_y_q - 1'b1;
        f_b_q <= cur_b;
        if (strobe && !done) f_iter_q <= f_iter_q + 1'b1;
      end
    end
  end

  // The position including the pulses shown in this clock, and its |p|^2:
  // (x +- 1)^2 = x^2 +- 2x + 1.
  logic signed [SW-1:0] cur_x, cur_y;
  logic signed [QW-1:0] cur_b, d_x, d_y;
  assign cur_x = step_x ? (dir_x ? f_x_q + 1'b1 : f_x_q - 1'b1) : f_x_q;
  assign cur_y = step_y ? (dir_y ? f_y_q + 1'b1 : f_y_q - 1'b1) : f_y_q;
  assign d_x = !step_x ? '0 : dir_x ? 2 * QW'(f_x_q) + 1 : -2 * QW'(f_x_q) + 1;
  assign d_y = !step_y ? '0 : dir_y ? 2 * QW'(f_y_q) + 1 : -2 * QW'(f_y_q) + 1;
  assign cur_b = f_b_q + d_x + d_y;

  always_comb begin
    assume (rst_ni == !f_init);
    // Only arcs the decoder accepts are loaded.
    if (load) assume (!geo_err && on_circle(a_now, b_end));
    // The words matter only at the load; zero elsewhere, so the solver drops the
    // multipliers of the other clocks.
    if (!load) assume ({dx_i, dx_neg_i, dy_i, dy_neg_i, i_i, i_neg_i, j_i, j_neg_i, ccw_i,
                        band_lo_i, band_hi_i} == '0);
    // The band: the squares b with |sqrt(b) - R0| <= 1 form the interval [lo, hi].
    if (load) begin
      assume (on_circle(a_now, QW'(band_lo_i)) && on_circle(a_now, QW'(band_hi_i)));
      assume (band_lo_i == '0 || !on_circle(a_now, QW'(band_lo_i) - 1));
      assume (!on_circle(a_now, QW'(band_hi_i) + 1));
    end
  end

  always_comb begin
    if (!f_init && f_loaded_q) begin
      if (done) begin
        ap_end_x: assert (cur_x == f_x1_q);
        ap_end_y: assert (cur_y == f_y1_q);
      end
      if (step_x) ap_dir_x: assert (dir_x == !f_neg_x_q);
      if (step_y) ap_dir_y: assert (dir_y == !f_neg_y_q);
      ap_finishes: assert (done || f_iter_q < 2 * f_kpow_q);
      ap_radial: assert (cur_b >= f_lo_q && cur_b <= f_hi_q);
    end
    if (!f_init) begin
      if (step_x) ap_step_x: assert (f_iter_edge_q);
      if (step_y) ap_step_y: assert (f_iter_edge_q);
    end
  end

  // Reachability: a full quadrant from axis to axis of the largest radius completes.
  always_comb begin
    if (!f_init) begin
      cp_arc_completes: cover (f_loaded_q && done && f_x1_q == '0 && f_y_q == f_y1_q
                               && f_y1_q == SW'((1 << W) - 1) && f_x_q != f_x1_q);
    end
  end

endmodule
