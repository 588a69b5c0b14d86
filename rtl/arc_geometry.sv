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
// Timing: purely combinational. With enable_i low every output is 0: the logic is only
// evaluated while an arc is prepared, which keeps the verilated model fast (a gate per
// output in hardware).
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
  output logic [IncWidth-1:0] x1_o,      // |E| per axis (low W bits; see error_o)
  output logic [IncWidth-1:0] y1_o,
  output logic                grow_x_o,  // |x| grows along the arc
  output logic                grow_y_o,
  output logic [KWidth-1:0]   k_o,
  output logic                error_o,
  output logic [3:0]          error_code_o
);

  // Signed values need W + 2 bits: |x1| = |x0 + dx| <= 2^(W+1) - 2.
  localparam int SWidth = IncWidth + 2;

  localparam logic [3:0] ErrTooWide       = 4'd4;
  localparam logic [3:0] ErrCrossQuadrant = 4'd10;
  localparam logic [3:0] ErrZeroRadius    = 4'd12;

  logic signed [SWidth-1:0] x0, y0, dx, dy, x1, y1;
  logic [SWidth-1:0]        x1_mag, y1_mag;
  logic                     x_plus, x_minus, y_plus, y_minus, moves, in_quadrant, too_wide;

  always_comb begin
    x0 = '0;  y0 = '0;  dx = '0;  dy = '0;  x1 = '0;  y1 = '0;  x1_mag = '0;  y1_mag = '0;
    x_plus = 1'b0;  x_minus = 1'b0;  y_plus = 1'b0;  y_minus = 1'b0;
    moves = 1'b0;  in_quadrant = 1'b0;  too_wide = 1'b0;
    x0_o = '0;  y0_o = '0;  x1_o = '0;  y1_o = '0;  grow_x_o = 1'b0;  grow_y_o = 1'b0;
    k_o = '0;
    error_o = 1'b0;
    error_code_o = ErrZeroRadius;
    if (enable_i) begin
      x0 = i_neg_i ? SWidth'(i_i) : -(SWidth'(i_i));  // start - centre = -I
      y0 = j_neg_i ? SWidth'(j_i) : -(SWidth'(j_i));
      dx = dx_neg_i ? -(SWidth'(dx_i)) : SWidth'(dx_i);
      dy = dy_neg_i ? -(SWidth'(dy_i)) : SWidth'(dy_i);
      x1 = x0 + dx;
      y1 = y0 + dy;
      x1_mag = x1[SWidth-1] ? -x1 : x1;
      y1_mag = y1[SWidth-1] ? -y1 : y1;

      // Votes for the quadrant's signs: the ends, and the motion (a ccw arc in the quadrant
      // (sx, sy) has sign(dy) = sx and sign(dx) = -sy; a cw arc the opposite).
      x_plus  = (x0 > 0) || (x1 > 0) || (ccw_i ? dy > 0 : dy < 0);
      x_minus = (x0 < 0) || (x1 < 0) || (ccw_i ? dy < 0 : dy > 0);
      y_plus  = (y0 > 0) || (y1 > 0) || (ccw_i ? dx < 0 : dx > 0);
      y_minus = (y0 < 0) || (y1 < 0) || (ccw_i ? dx > 0 : dx < 0);
      moves       = dx_i != '0 || dy_i != '0;
      in_quadrant = moves && !(x_plus && x_minus) && !(y_plus && y_minus);
      too_wide    = x1_mag[SWidth-1:IncWidth] != '0 || y1_mag[SWidth-1:IncWidth] != '0;

      error_o      = 1'b1;
      error_code_o = ErrZeroRadius;
      if (i_i == '0 && j_i == '0) begin
        error_code_o = ErrZeroRadius;
      end else if (!in_quadrant) begin
        error_code_o = ErrCrossQuadrant;
      end else if (too_wide) begin
        error_code_o = ErrTooWide;
      end else begin
        error_o = 1'b0;
      end

      x0_o     = i_i;
      y0_o     = j_i;
      x1_o     = x1_mag[IncWidth-1:0];
      y1_o     = y1_mag[IncWidth-1:0];
      grow_x_o = x1_mag > SWidth'(i_i);
      grow_y_o = y1_mag > SWidth'(j_i);
      // k: position of the highest 1 of any magnitude, plus one (a priority encoder).
      for (int b = 0; b < IncWidth; b++) begin
        if (i_i[b] || j_i[b] || x1_o[b] || y1_o[b]) k_o = KWidth'(b + 1);
      end
    end
  end

endmodule
