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
// arc_radius_check.sv. The golden twin is sc_model/golden/arc_geometry.cpp.
// How (lean): everything stays in sign + magnitude, one W + 1-bit adder per axis. |x1| is
// |x0| + |dx| when the move goes away from the centre's axis (or x0 = 0) and |x0| - |dx|
// when it goes towards it; a negative difference means the end crossed the axis, which is
// a quadrant error, so |x1| is only needed (and only exact) when it did not cross. The
// magnitude then grows exactly when it is a sum and the move is not zero.
// Timing: purely combinational. The outputs are used only with enable_i high; with it low
// they are don't-care ('x): the verilated model skips the logic (fast), and synthesis
// folds the 'x away, so the enable costs no gate.
module arc_geometry #(
  parameter int IncWidth = 16,
  parameter int KWidth   = $clog2(IncWidth + 1)
) (
  input  logic                enable_i,  // the outputs are used in this clock
  input  logic [IncWidth-1:0] dx_i,
  input  logic                dx_neg_i,
  input  logic [IncWidth-1:0] dy_i,
  input  logic                dy_neg_i,
  input  logic [IncWidth-1:0] i_i,
  input  logic                i_neg_i,
  input  logic [IncWidth-1:0] j_i,
  input  logic                j_neg_i,
  input  logic                ccw_i,     // G03 (else G02)
  output logic [IncWidth-1:0] x0_o,      // |S| per axis
  output logic [IncWidth-1:0] y0_o,
  output logic [IncWidth-1:0] x1_o,      // |E| per axis (when the arc passes the checks)
  output logic [IncWidth-1:0] y1_o,
  output logic                grow_x_o,  // |x| grows along the arc
  output logic                grow_y_o,
  output logic                add_x_o,   // |x1| = |x0| + |dx| (else |x0| - |dx|)
  output logic                add_y_o,
  output logic [KWidth-1:0]   k_o,
  output logic                error_o,
  output logic [3:0]          error_code_o
);


  // One axis: start magnitude s (sign: s_pos, the start is -I so it is positive when I is
  // negative), move d (d_pos). Result {plus, minus, end_mag, grow, too_wide}: the signs of
  // the start and the end as votes for the quadrant's sign, the end's magnitude, whether it
  // grows and whether it overflows the register.
  localparam int AxisWidth = IncWidth + 5;
  function automatic logic [AxisWidth-1:0] axis(input logic [IncWidth-1:0] s, input logic s_pos,
                                                input logic [IncWidth-1:0] d, input logic d_pos);
    logic              s_zero, d_zero, away, end_pos, end_zero;
    logic [IncWidth:0] r;
    s_zero = s == '0;
    d_zero = d == '0;
    // Away from the axis (or from it, x0 = 0): a sum; towards it: a difference.
    away     = s_zero || s_pos == d_pos;
    // One adder: s + d, or s - d as s + ~d + 1.
    r        = {1'b0, s} + ({1'b0, d} ^ {(IncWidth + 1){!away}}) + (IncWidth + 1)'(!away);
    end_zero = r == '0;
    // A negative difference: the end is on the move's side of the axis (crossed it).
    end_pos  = away ? (s_zero ? d_pos : s_pos) : (r[IncWidth] ? d_pos : s_pos);
    axis = {(!s_zero && s_pos) || (!end_zero && end_pos),
            (!s_zero && !s_pos) || (!end_zero && !end_pos),
            r[IncWidth-1:0], away && !d_zero, away && r[IncWidth], away};
  endfunction

  logic                ax_plus, ax_minus, ax_grow, ax_too_wide, ax_add;
  logic                ay_plus, ay_minus, ay_grow, ay_too_wide, ay_add;
  logic [IncWidth-1:0] ax_end, ay_end;
  logic  dx_plus, dx_minus, dy_plus, dy_minus, moves, in_quadrant;
  logic [IncWidth-1:0] all_bits;

  always_comb begin
    {ax_plus, ax_minus, ax_end, ax_grow, ax_too_wide, ax_add} = 'x;
    {ay_plus, ay_minus, ay_end, ay_grow, ay_too_wide, ay_add} = 'x;
    {dx_plus, dx_minus, dy_plus, dy_minus, moves, in_quadrant} = 'x;
    all_bits = 'x;
    x0_o = 'x;  y0_o = 'x;  x1_o = 'x;  y1_o = 'x;  grow_x_o = 1'bx;  grow_y_o = 1'bx;
    add_x_o = 1'bx;  add_y_o = 1'bx;
    k_o = 'x;
    error_o = 1'bx;
    error_code_o = interp_pkg::ErrArcZeroRadius;
    if (enable_i) begin
      {ax_plus, ax_minus, ax_end, ax_grow, ax_too_wide, ax_add} =
          axis(i_i, i_neg_i, dx_i, !dx_neg_i);
      {ay_plus, ay_minus, ay_end, ay_grow, ay_too_wide, ay_add} =
          axis(j_i, j_neg_i, dy_i, !dy_neg_i);
      dx_plus  = dx_i != '0 && !dx_neg_i;
      dx_minus = dx_i != '0 && dx_neg_i;
      dy_plus  = dy_i != '0 && !dy_neg_i;
      dy_minus = dy_i != '0 && dy_neg_i;
      // Votes for the quadrant's signs: the ends, and the motion (a ccw arc in the quadrant
      // (sx, sy) has sign(dy) = sx and sign(dx) = -sy; a cw arc the opposite).
      moves       = dx_plus || dx_minus || dy_plus || dy_minus;
      in_quadrant = moves &&
                    !((ax_plus || (ccw_i ? dy_plus : dy_minus)) &&
                      (ax_minus || (ccw_i ? dy_minus : dy_plus))) &&
                    !((ay_plus || (ccw_i ? dx_minus : dx_plus)) &&
                      (ay_minus || (ccw_i ? dx_plus : dx_minus)));

      error_o = 1'b1;
      if (i_i == '0 && j_i == '0) begin
        error_code_o = interp_pkg::ErrArcZeroRadius;
      end else if (!in_quadrant) begin
        error_code_o = interp_pkg::ErrArcCrossesQuadrant;
      end else if (ax_too_wide || ay_too_wide) begin
        error_code_o = interp_pkg::ErrValueTooWide;
      end else begin
        error_o = 1'b0;
      end

      x0_o     = i_i;
      y0_o     = j_i;
      x1_o     = ax_end;
      y1_o     = ay_end;
      grow_x_o = ax_grow;
      grow_y_o = ay_grow;
      add_x_o  = ax_add;
      add_y_o  = ay_add;
      // k: position of the highest 1 of any magnitude, plus one (a priority encoder).
      all_bits = i_i | j_i | ax_end | ay_end;
      for (int b = 0; b < IncWidth; b++) begin
        if (all_bits[b]) k_o = KWidth'(b + 1);
      end
    end
  end

endmodule
