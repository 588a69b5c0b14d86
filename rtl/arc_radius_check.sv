// Radius check of an arc block: is the end at most 1 BLU off the circle through the start?
//
// What: with A = x0^2 + y0^2 (>= 1) and B = x1^2 + y1^2 (magnitudes relative to the
// centre), |sqrt(B) - sqrt(A)| <= 1 exactly when (B - A - 1)^2 <= 4A. The squares are
// computed bit-serially, MSB first (acc = 2 acc + v * v[b]), so the check needs adders
// only: W steps compute A and B together, one step forms E = B - A - 1 (|E| >= 2^(W+2)
// fails at once, since 4A < 2^(2W+3)), and W + 2 steps square |E|. The golden twin is in
// sc_model/golden/arc_prepare.cpp; the exact formula is arc_end_on_circle().
// Timing: start_i at an edge clears the check; the next 2W + 3 edges are its steps; from
// then on done_o = 1 and ok_o is the result. The operands must stay constant from the start
// edge to done (they are the decoder's held block).
module arc_radius_check #(
  parameter int IncWidth = 16
) (
  input  logic                clk_i,
  input  logic                rst_ni,
  input  logic                start_i,
  input  logic [IncWidth-1:0] x0_i,
  input  logic [IncWidth-1:0] y0_i,
  input  logic [IncWidth-1:0] x1_i,
  input  logic [IncWidth-1:0] y1_i,
  output logic                done_o,
  output logic                ok_o
);

  localparam int Steps      = 2 * IncWidth + 3;
  localparam int CountWidth = $clog2(Steps + 1);
  localparam int AWidth     = 2 * IncWidth + 1;  // x0^2 + y0^2 < 2^(2W+1)
  localparam int EWidth     = IncWidth + 2;      // |E| when it can pass
  localparam int SqWidth    = 2 * IncWidth + 4;  // B, then |E|^2 < 2^(2W+4)
  localparam int AbIndexWidth = $clog2(IncWidth);          // a bit of x0, y0, x1, y1
  localparam int EIndexWidth  = $clog2(EWidth);            // a bit of |E|
  localparam logic [CountWidth-1:0] StepsCount = CountWidth'(Steps);
  localparam logic [CountWidth-1:0] SquareEnd  = CountWidth'(IncWidth);

  // count_q: steps done (Steps = finished; reset value, so an idle check reads done).
  // a_q: A being accumulated. sq_q: B being accumulated, then |E|^2. e_q: |E| (low bits).
  // far_q: |E| >= 2^(W+2), the end is far off the circle.
  logic [CountWidth-1:0] count_q, count_d;
  logic [AWidth-1:0]     a_q, a_d;
  logic [SqWidth-1:0]    sq_q, sq_d;
  logic [EWidth-1:0]     e_q, e_d;
  logic                  far_q, far_d;

  logic [AbIndexWidth-1:0]    bit_ab;
  logic [EIndexWidth-1:0]     bit_e;
  logic signed [SqWidth:0]    e_full;
  logic [SqWidth:0]           e_mag;

  // The registers change only at the start and while the check runs; the other clocks
  // evaluate nothing here (a fast verilated model).
  logic active;
  assign active = start_i || count_q != StepsCount;

  always_comb begin
    bit_ab  = '0;
    bit_e   = '0;
    e_full  = '0;
    e_mag   = '0;
    count_d = '0;
    a_d     = '0;
    sq_d    = '0;
    e_d     = '0;
    far_d   = 1'b0;
    // start_i: everything cleared (the defaults above); idle: the defaults are not stored.
    if (active && !start_i) begin
      // The bit a step uses, MSB first (modulo arithmetic on the low bits is exact here).
      bit_ab  = AbIndexWidth'(IncWidth - 1) - count_q[AbIndexWidth-1:0];  // W-1 .. 0, count < W
      bit_e   = EIndexWidth'(Steps - 1) - count_q[EIndexWidth-1:0];       // W+1 .. 0, count > W
      count_d = count_q + 1'b1;
      a_d     = a_q;
      sq_d    = sq_q;
      e_d     = e_q;
      far_d   = far_q;
      if (count_q < SquareEnd) begin
        a_d  = {a_q[AWidth-2:0], 1'b0}
             + (x0_i[bit_ab] ? AWidth'(x0_i) : '0)
             + (y0_i[bit_ab] ? AWidth'(y0_i) : '0);
        sq_d = {sq_q[SqWidth-2:0], 1'b0}
             + (x1_i[bit_ab] ? SqWidth'(x1_i) : '0)
             + (y1_i[bit_ab] ? SqWidth'(y1_i) : '0);
      end else if (count_q == SquareEnd) begin
        e_full = $signed({1'b0, sq_q}) - $signed({1'b0, {(SqWidth - AWidth){1'b0}}, a_q}) - 1;
        e_mag  = e_full[SqWidth] ? -e_full : e_full;
        far_d = e_mag[SqWidth:EWidth] != '0;
        e_d   = e_mag[EWidth-1:0];
        sq_d  = '0;
      end else begin
        sq_d = {sq_q[SqWidth-2:0], 1'b0} + (e_q[bit_e] ? SqWidth'(e_q) : '0);
      end
    end
  end

  always_ff @(posedge clk_i) begin
    if (!rst_ni) begin
      count_q <= StepsCount;
      a_q     <= '0;
      sq_q    <= '0;
      e_q     <= '0;
      far_q   <= 1'b0;
    end else if (active) begin
      count_q <= count_d;
      a_q     <= a_d;
      sq_q    <= sq_d;
      e_q     <= e_d;
      far_q   <= far_d;
    end
  end

  assign done_o = count_q == StepsCount;
  assign ok_o   = !far_q && sq_q <= {1'b0, a_q, 2'b00};  // |E|^2 <= 4A

endmodule
