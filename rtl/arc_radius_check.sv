// Radius check of an arc block: is the end at most 1 BLU off the circle through the start?
//
// What: with A = x0^2 + y0^2 (>= 1) and B = x1^2 + y1^2 (magnitudes relative to the
// centre), |sqrt(B) - sqrt(A)| <= 1 exactly when (B - A - 1)^2 <= 4A. Everything runs on
// one adder and one accumulator, serially (the 1960s way; the check has the whole dry run
// of the arc to finish): the squares MSB first by shift-and-add (acc = 2 acc + v * v[b],
// the other term of the sum of squares added in the next clock), E = B - A - 1 as
// B + ~A, |E| by ~E + 1, and |E|^2 again by shift-and-add. |E| >= 2^(W+2) fails at once,
// since 4A < 2^(2W+3). The golden twin is ArcRadiusCheck
// (sc_model/golden/arc_radius_check.h); the exact formula is arc_end_on_circle().
// Schedule (5W + 5 clocks after start_i):
//   SumA  2W clocks  acc = 2 acc + x0 x0[b], then acc += y0 y0[b], b = W-1 .. 0; the
//                    last sum goes to a (A), acc is cleared
//   SumB  2W clocks  the same with x1, y1: acc = B
//   Diff  1 clock    acc = B + ~A = E (two's complement)
//   Abs   1 clock    acc = |E| (~E + 1 if negative)
//   Split 1 clock    far = |E| >= 2^(W+2); e = |E| (W + 2 bits); acc cleared
//   Sq    W+2 clocks acc = 2 acc + e e[b], b = W+1 .. 0: acc = |E|^2
//   Done             ok_o = !far && acc <= 4A
// The operands must stay constant from the start edge to done (the decoder's held block).
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

  localparam int AWidth     = 2 * IncWidth + 1;  // x0^2 + y0^2 < 2^(2W+1)
  localparam int EWidth     = IncWidth + 2;      // |E| when it can pass
  localparam int SqWidth    = 2 * IncWidth + 4;  // E (signed), |E|^2 < 2^(2W+4)
  localparam int IndexWidth = $clog2(EWidth);    // a bit of x0 .. y1 or of e
  localparam logic [IndexWidth-1:0] TopSum = IndexWidth'(IncWidth - 1);
  localparam logic [IndexWidth-1:0] TopSq  = IndexWidth'(EWidth - 1);

  typedef enum logic [2:0] {SumA, SumB, Diff, Abs, Split, Sq, Done} phase_e;

  // phase_q, bit_q: where the schedule is; second_q: the y term of a sum of squares.
  // acc_q: the accumulator. a_q: A. e_q: |E| (low bits). far_q: |E| >= 2^(W+2).
  phase_e                phase_q;
  logic [IndexWidth-1:0] bit_q;
  logic                  second_q;
  logic [SqWidth-1:0]    acc_q;
  logic [AWidth-1:0]     a_q;
  logic [EWidth-1:0]     e_q;
  logic                  far_q;

  // The adder: acc = op_a + op_b + carry.
  logic [SqWidth-1:0]  op_a, op_b, sum;
  logic                carry;
  logic [IncWidth-1:0] x, y;
  logic [EWidth-1:0]   v;  // the squared operand of a sum step, widened like e_q
  logic                active, last_bit;

  // The registers change only at the start and while the check runs; the other clocks
  // evaluate nothing here (a fast verilated model).
  assign active   = start_i || phase_q != Done;
  assign last_bit = bit_q == '0;

  always_comb begin
    // The sum is stored only while the check runs: don't-care ('x) otherwise.
    {op_a, op_b, carry, x, y, v} = 'x;
    if (active && !start_i) begin
      {op_a, op_b, carry} = '0;
      x = phase_q == SumA ? x0_i : x1_i;
      y = phase_q == SumA ? y0_i : y1_i;
      v = second_q ? {2'b00, y} : {2'b00, x};
      unique case (phase_q)
        SumA, SumB: begin
          op_a = second_q ? acc_q : {acc_q[SqWidth-2:0], 1'b0};
          op_b = v[bit_q] ? SqWidth'(v) : '0;
        end
        Diff: begin
          op_a = acc_q;
          op_b = ~{{(SqWidth - AWidth){1'b0}}, a_q};
        end
        Abs: begin
          op_b  = acc_q[SqWidth-1] ? ~acc_q : acc_q;
          carry = acc_q[SqWidth-1];
        end
        Sq: begin
          op_a = {acc_q[SqWidth-2:0], 1'b0};
          op_b = e_q[bit_q] ? SqWidth'(e_q) : '0;
        end
        default: ;  // Split, Done: no sum
      endcase
    end
  end

  assign sum = op_a + op_b + SqWidth'(carry);

  always_ff @(posedge clk_i) begin
    if (!rst_ni) begin
      phase_q  <= Done;
      bit_q    <= '0;
      second_q <= 1'b0;
      acc_q    <= '0;
      a_q      <= '0;
      e_q      <= '0;
      far_q    <= 1'b0;
    end else if (start_i) begin
      phase_q  <= SumA;
      bit_q    <= TopSum;
      second_q <= 1'b0;
      acc_q    <= '0;
    end else if (active) begin
      unique case (phase_q)
        SumA, SumB: begin
          acc_q    <= sum;
          second_q <= !second_q;
          if (second_q) begin
            bit_q <= bit_q - 1'b1;
            if (last_bit) begin
              bit_q <= TopSum;
              if (phase_q == SumA) begin
                a_q     <= sum[AWidth-1:0];
                acc_q   <= '0;
                phase_q <= SumB;
              end else begin
                phase_q <= Diff;
              end
            end
          end
        end
        Diff: begin
          acc_q   <= sum;
          phase_q <= Abs;
        end
        Abs: begin
          acc_q   <= sum;
          phase_q <= Split;
        end
        Split: begin
          far_q   <= acc_q[SqWidth-1:EWidth] != '0;
          e_q     <= acc_q[EWidth-1:0];
          acc_q   <= '0;
          bit_q   <= TopSq;
          phase_q <= Sq;
        end
        Sq: begin
          acc_q <= sum;
          bit_q <= bit_q - 1'b1;
          if (last_bit) phase_q <= Done;
        end
        default: ;
      endcase
    end
  end

  assign done_o = phase_q == Done;
  assign ok_o   = !far_q && acc_q <= {1'b0, a_q, 2'b00};  // |E|^2 <= 4A

endmodule
