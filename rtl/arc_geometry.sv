// Geometry of a quadrant arc block and its immediate checks.
//
// What: from the block's words (X, Y, I, J as magnitude + sign, G02/G03) the start relative
// to the centre S = (-I, -J) and the end E = S + (X, Y); their magnitudes per axis, whether
// each magnitude grows along the arc, and k = bit length of the largest magnitude (the
// circle DDA's modulus 2^k). Checks, first failing one reported (docs/circle-dda.md 2):
// zero radius (I = J = 0, code 12); not inside one quadrant (code 10): both ends must lie
// in one closed quadrant and each coordinate must move the way the arc's direction goes
// there, i.e. the nonzero signs among x0, x1 and (ccw ? dy : -dy) agree, and so do those
// among y0, y1 and (ccw ? -dx : dx), and the move is not zero; the end outside the
// increment register (|x1| or |y1| > 2^W - 1, code 4). The radius check (code 11) is
// arc_radius_check.sv. The golden twin is sc_model/golden/arc_geometry.cpp (the results;
// ArcPrepare, sc_model/golden/arc_prepare.cpp, has the clocks of the serial form).
// How (lean): everything stays in sign + magnitude, one W + 1-bit sum per axis. |x1| is
// |x0| + |dx| when the move goes away from the centre's axis (or x0 = 0) and |x0| - |dx|
// when it goes towards it (add_x_o); a negative difference means the end crossed the axis,
// which is a quadrant error, so |x1| is only needed (and only exact) when it did not cross.
// The magnitude then grows exactly when it is a sum and the move is not zero. What decides
// sum or difference (the magnitudes' zero-ness and the signs) is read in parallel.
// Two forms (BitSerial):
//   0: the sums on two W + 1-bit adders, all outputs combinational (used only with
//      enable_i high; with it low they are don't-care ('x): the verilated model skips the
//      logic and synthesis folds the 'x away, so the enable costs no gate). done_o =
//      enable_i; the clock is not used and the words never turn.
//   1 (the board's): the sums on one one-bit adder per axis while the decoder's magnitudes
//      turn one place per clock (shift_o; bit 0 passes LSB first, as for the radius check,
//      arc_radius_check.sv), and k, the end's zero-ness and the top carry followed bit by
//      bit: no W-bit adder, zero compare of the end or priority encoder. The first clock
//      with enable_i is edge S; edges S+1 .. S+W take bits 0 .. W-1 (shift_o); done_o and
//      the results from edge S+W on (the words back in place) until enable_i falls.
// The magnitudes themselves are not outputs: |x0|, |y0| are |I|, |J| as they are, and the
// radius check forms |x1|, |y1| itself, bit-serially (arc_radius_check.sv).
module arc_geometry #(
  parameter int IncWidth  = 16,
  parameter int KWidth    = $clog2(IncWidth + 1),
  parameter bit BitSerial = 1'b0
) (
  input  logic                clk_i,
  input  logic                rst_ni,
  input  logic                enable_i,  // the arc is being prepared
  input  logic [IncWidth-1:0] dx_i,
  input  logic                dx_neg_i,
  input  logic [IncWidth-1:0] dy_i,
  input  logic                dy_neg_i,
  input  logic [IncWidth-1:0] i_i,
  input  logic                i_neg_i,
  input  logic [IncWidth-1:0] j_i,
  input  logic                j_neg_i,
  input  logic                ccw_i,     // G03 (else G02)
  output logic                shift_o,   // BitSerial: the magnitudes turn at this edge
  output logic                done_o,    // the outputs below are valid in this clock
  output logic                grow_x_o,  // |x| grows along the arc
  output logic                grow_y_o,
  output logic                add_x_o,   // |x1| = |x0| + |dx| (else |x0| - |dx|)
  output logic                add_y_o,
  output logic [KWidth-1:0]   k_o,
  output logic                error_o,
  output logic [interp_pkg::ErrCodeWidth-1:0] error_code_o
);

  // Per axis, from the sum: the end's magnitude is 0 (end_zero), its carry out of bit W - 1
  // (top: for a difference, set when the end did not cross the axis).
  logic                s_zero_x, s_zero_y, d_zero_x, d_zero_y, s_pos_x, s_pos_y;
  logic                d_pos_x, d_pos_y, add_x, add_y;
  logic                end_zero_x, end_zero_y, top_x, top_y;
  logic [KWidth-1:0]   k;

  // What decides sum or difference: it does not change when the magnitudes turn.
  assign s_zero_x = i_i == '0;
  assign s_zero_y = j_i == '0;
  assign d_zero_x = dx_i == '0;
  assign d_zero_y = dy_i == '0;
  assign s_pos_x  = i_neg_i;  // the start is -I: positive when I is negative
  assign s_pos_y  = j_neg_i;
  assign d_pos_x  = !dx_neg_i;
  assign d_pos_y  = !dy_neg_i;
  // Away from the axis (or from it, x0 = 0): a sum; towards it: a difference.
  assign add_x    = s_zero_x || s_pos_x == d_pos_x;
  assign add_y    = s_zero_y || s_pos_y == d_pos_y;

  if (!BitSerial) begin : g_parallel
    // One adder per axis: s + d, or s - d as s + ~d + 1.
    logic [IncWidth:0]   r_x, r_y;
    logic [IncWidth-1:0] all_bits;
    always_comb begin
      {r_x, r_y, end_zero_x, end_zero_y, top_x, top_y, all_bits, k} = 'x;
      if (enable_i) begin
        r_x = {1'b0, i_i} + ({1'b0, dx_i} ^ {(IncWidth + 1){!add_x}}) + (IncWidth + 1)'(!add_x);
        r_y = {1'b0, j_i} + ({1'b0, dy_i} ^ {(IncWidth + 1){!add_y}}) + (IncWidth + 1)'(!add_y);
        end_zero_x = r_x == '0;
        end_zero_y = r_y == '0;
        top_x = r_x[IncWidth] ^ !add_x;
        top_y = r_y[IncWidth] ^ !add_y;
        // k: position of the highest 1 of any magnitude, plus one (a priority encoder).
        all_bits = i_i | j_i | r_x[IncWidth-1:0] | r_y[IncWidth-1:0];
        k = '0;
        for (int b = 0; b < IncWidth; b++) begin
          if (all_bits[b]) k = KWidth'(b + 1);
        end
      end
    end
    assign done_o  = enable_i;
    assign shift_o = 1'b0;
    /* verilator lint_off UNUSEDSIGNAL */
    logic unused_serial;
    /* verilator lint_on UNUSEDSIGNAL */
    assign unused_serial = ^{clk_i, rst_ni};
  end else begin : g_serial
    // Schedule: bit_q is the bit of this clock while busy_q; carry_*_q the one-bit adders'
    // carries (at the end: the carries out of bit W - 1); nonzero_*_q the end's bits so far;
    // k_q the highest bit so far that any magnitude has set, plus one.
    logic [KWidth-1:0] bit_q, k_q;
    logic              busy_q, done_q, carry_x_q, carry_y_q, nonzero_x_q, nonzero_y_q;
    logic              sum_x, sum_y, cout_x, cout_y, last, start;
    assign start = enable_i && !busy_q && !done_q;
    assign {cout_x, sum_x} = {1'b0, i_i[0]} + {1'b0, dx_i[0] ^ !add_x} + {1'b0, carry_x_q};
    assign {cout_y, sum_y} = {1'b0, j_i[0]} + {1'b0, dy_i[0] ^ !add_y} + {1'b0, carry_y_q};
    assign last = bit_q == KWidth'(IncWidth - 1);
    always_ff @(posedge clk_i) begin
      if (!rst_ni || !enable_i) begin
        {busy_q, done_q} <= '0;
        bit_q <= '0;
      end else if (start) begin
        busy_q      <= 1'b1;
        bit_q       <= '0;
        k_q         <= '0;
        carry_x_q   <= !add_x;  // s - d = s + ~d + 1
        carry_y_q   <= !add_y;
        nonzero_x_q <= 1'b0;
        nonzero_y_q <= 1'b0;
      end else if (busy_q) begin
        bit_q       <= bit_q + 1'b1;
        carry_x_q   <= cout_x;
        carry_y_q   <= cout_y;
        nonzero_x_q <= nonzero_x_q || sum_x;
        nonzero_y_q <= nonzero_y_q || sum_y;
        if (i_i[0] || j_i[0] || sum_x || sum_y) k_q <= bit_q + 1'b1;
        if (last) {busy_q, done_q} <= 2'b01;
      end
    end
    assign end_zero_x = !nonzero_x_q;
    assign end_zero_y = !nonzero_y_q;
    assign top_x      = carry_x_q;
    assign top_y      = carry_y_q;
    assign k          = k_q;
    assign done_o     = done_q;
    assign shift_o    = busy_q;
  end

  // The checks, from the sums (valid with done_o).
  logic  end_pos_x, end_pos_y, ax_plus, ax_minus, ay_plus, ay_minus;
  logic  dx_plus, dx_minus, dy_plus, dy_minus, moves, in_quadrant;
  always_comb begin
    {end_pos_x, end_pos_y, ax_plus, ax_minus, ay_plus, ay_minus} = 'x;
    {dx_plus, dx_minus, dy_plus, dy_minus, moves, in_quadrant} = 'x;
    grow_x_o = 1'bx;  grow_y_o = 1'bx;  k_o = 'x;  error_o = 1'bx;
    error_code_o = interp_pkg::ErrArcZeroRadius;
    if (done_o) begin
      // A difference that did not carry out is negative: the end is on the move's side of
      // the axis (crossed it).
      end_pos_x = add_x ? (s_zero_x ? d_pos_x : s_pos_x) : (top_x ? s_pos_x : d_pos_x);
      end_pos_y = add_y ? (s_zero_y ? d_pos_y : s_pos_y) : (top_y ? s_pos_y : d_pos_y);
      // The signs of the start and the end as votes for the quadrant's sign.
      ax_plus  = (!s_zero_x && s_pos_x) || (!end_zero_x && end_pos_x);
      ax_minus = (!s_zero_x && !s_pos_x) || (!end_zero_x && !end_pos_x);
      ay_plus  = (!s_zero_y && s_pos_y) || (!end_zero_y && end_pos_y);
      ay_minus = (!s_zero_y && !s_pos_y) || (!end_zero_y && !end_pos_y);
      dx_plus  = !d_zero_x && d_pos_x;
      dx_minus = !d_zero_x && !d_pos_x;
      dy_plus  = !d_zero_y && d_pos_y;
      dy_minus = !d_zero_y && !d_pos_y;
      // Votes for the quadrant's signs: the ends, and the motion (a ccw arc in the quadrant
      // (sx, sy) has sign(dy) = sx and sign(dx) = -sy; a cw arc the opposite).
      moves       = dx_plus || dx_minus || dy_plus || dy_minus;
      in_quadrant = moves &&
                    !((ax_plus || (ccw_i ? dy_plus : dy_minus)) &&
                      (ax_minus || (ccw_i ? dy_minus : dy_plus))) &&
                    !((ay_plus || (ccw_i ? dx_minus : dx_plus)) &&
                      (ay_minus || (ccw_i ? dx_plus : dx_minus)));

      error_o = 1'b1;
      if (s_zero_x && s_zero_y) begin
        error_code_o = interp_pkg::ErrArcZeroRadius;
      end else if (!in_quadrant) begin
        error_code_o = interp_pkg::ErrArcCrossesQuadrant;
      end else if ((add_x && top_x) || (add_y && top_y)) begin
        error_code_o = interp_pkg::ErrValueTooWide;
      end else begin
        error_o = 1'b0;
      end
      grow_x_o = add_x && !d_zero_x;
      grow_y_o = add_y && !d_zero_y;
      k_o      = k;
    end
  end

  assign add_x_o = add_x;
  assign add_y_o = add_y;

endmodule
