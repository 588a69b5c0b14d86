// Formal harness of the bit-serial radius check (rtl/arc_radius_check.sv) against its plain
// specification, at width W.
//
// What is proven: for every arc's words whose verdict counts (|x0|, |y0| of the start about
// the centre with A = x0^2 + y0^2 >= 1, |dx|, |dy|, and the geometry's choice of
// |x1| = |x0| + |dx| or |x0| - |dx|, likewise y, in [0, 2^W): arc_geometry.sv refuses the
// others), started at one edge and read bit by bit through the words' turns (shift_o) as
// the decoder turns them:
// - ap_done: the check is done exactly (5W + 4)(2W + 4) clocks after its start, and not
//   before;
// - ap_ok: its verdict ok_o is the specification's, (B - A - 1)^2 <= 4A with
//   B = x1^2 + y1^2: the end is within 1 BLU of the circle through the start
//   (docs/circle-dda.md 2.2), computed here with plain multiplications;
// - ap_words: the words are back in place when it is done (the decoder's block is intact).
// The bound: the check's whole run is (5W + 4)(2W + 4) + 2 steps, so BMC to that depth
// covers every input at width W: at that width the proof is complete. The covers show a
// passing and a failing verdict.
module arc_radius_check_props #(
  parameter int W = 2
) (
  input logic         clk_i,
  input logic         rst_ni,
  input logic [W-1:0] x0_i,
  input logic [W-1:0] y0_i,
  input logic [W-1:0] dx_i,
  input logic [W-1:0] dy_i,
  input logic         add_x_i,
  input logic         add_y_i
);

  localparam int Clocks = (5 * W + 4) * (2 * W + 4);
  localparam int CW = $clog2(Clocks + 2);
  localparam int QW = 2 * W + 4;   // squares and E = B - A - 1, signed
  localparam int RW = 2 * QW;      // E^2

  logic       f_init = 1'b1;
  logic [1:0] f_age_q;  // edges since reset, saturating at 2
  logic       start;
  assign start = f_age_q == 2'd1;

  // The decoder's words, turning one place at each edge with shift_o.
  logic [W-1:0] f_x0_q, f_y0_q, f_dx_q, f_dy_q;
  logic         f_add_x_q, f_add_y_q;
  logic         shift, done, ok;
  arc_radius_check #(.IncWidth(W)) u_dut (
    .clk_i, .rst_ni, .start_i(start),
    .x0_bit_i(f_x0_q[0]), .y0_bit_i(f_y0_q[0]), .dx_bit_i(f_dx_q[0]), .dy_bit_i(f_dy_q[0]),
    .add_x_i(f_add_x_q), .add_y_i(f_add_y_q), .shift_o(shift), .done_o(done), .ok_o(ok)
  );

  // The specification, from the words at the start.
  logic [W:0]           x1, y1;
  logic signed [QW-1:0] a, b, e;
  logic signed [RW-1:0] e2;
  logic                 expect_ok;
  assign x1 = add_x_i ? (W + 1)'(x0_i) + (W + 1)'(dx_i) : (W + 1)'(x0_i) - (W + 1)'(dx_i);
  assign y1 = add_y_i ? (W + 1)'(y0_i) + (W + 1)'(dy_i) : (W + 1)'(y0_i) - (W + 1)'(dy_i);
  assign a  = QW'(x0_i) * QW'(x0_i) + QW'(y0_i) * QW'(y0_i);
  assign b  = QW'(x1) * QW'(x1) + QW'(y1) * QW'(y1);
  assign e  = b - a - 1;
  assign e2 = RW'(e) * RW'(e);
  assign expect_ok = e2 <= 4 * RW'(a);

  // Model: the words (held, turned with shift), the verdict expected, clocks since the start.
  logic          f_started_q, f_expect_q;
  logic [W-1:0]  f_x0_s, f_y0_s, f_dx_s, f_dy_s;  // the words as started
  logic [CW-1:0] f_clock_q;
  always_ff @(posedge clk_i) begin
    f_init <= 1'b0;
    if (!rst_ni) begin
      f_age_q <= '0;
      f_started_q <= 1'b0;  f_expect_q <= 1'b0;  f_clock_q <= '0;
      {f_x0_q, f_y0_q, f_dx_q, f_dy_q, f_add_x_q, f_add_y_q} <= '0;
      {f_x0_s, f_y0_s, f_dx_s, f_dy_s} <= '0;
    end else begin
      if (f_age_q != 2'd2) f_age_q <= f_age_q + 1'b1;
      if (start) begin
        f_started_q <= 1'b1;
        f_expect_q  <= expect_ok;
        f_clock_q   <= '0;
        {f_x0_q, f_y0_q, f_dx_q, f_dy_q} <= {x0_i, y0_i, dx_i, dy_i};
        {f_x0_s, f_y0_s, f_dx_s, f_dy_s} <= {x0_i, y0_i, dx_i, dy_i};
        {f_add_x_q, f_add_y_q} <= {add_x_i, add_y_i};
      end else begin
        if (f_started_q && !done) f_clock_q <= f_clock_q + 1'b1;
        if (shift) begin
          f_x0_q <= {f_x0_q[0], f_x0_q[W-1:1]};
          f_y0_q <= {f_y0_q[0], f_y0_q[W-1:1]};
          f_dx_q <= {f_dx_q[0], f_dx_q[W-1:1]};
          f_dy_q <= {f_dy_q[0], f_dy_q[W-1:1]};
        end
      end
    end
  end

  always_comb begin
    assume (rst_ni == !f_init);
    if (start) begin
      // What the check is asked about (arc_prepare.sv uses its verdict only for an arc the
      // geometry accepts, arc_geometry.sv): a non-zero radius, and end magnitudes
      // |x1|, |y1| that are >= 0 (the geometry's choice of sum or difference) and fit the
      // increment register (< 2^W).
      assume (x0_i != '0 || y0_i != '0);
      assume (!x1[W] && !y1[W]);
    end else begin
      assume ({x0_i, y0_i, dx_i, dy_i, add_x_i, add_y_i} == '0);
    end
  end

  always_comb begin
    if (!f_init && f_started_q) begin
      ap_done: assert (done == (f_clock_q == CW'(Clocks)));
      if (done) begin
        ap_ok: assert (ok == f_expect_q);
        ap_words: assert ({f_x0_q, f_y0_q, f_dx_q, f_dy_q} == {f_x0_s, f_y0_s, f_dx_s, f_dy_s});
      end
    end
  end

  always_comb begin
    if (!f_init) begin
      cp_passes: cover (f_started_q && done && ok);
      cp_fails: cover (f_started_q && done && !ok);
    end
  end

endmodule
