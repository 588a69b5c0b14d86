// Radius check of an arc block: is the end at most 1 BLU off the circle through the start?
//
// What: with A = x0^2 + y0^2 (>= 1) and B = x1^2 + y1^2 (magnitudes relative to the
// centre), |sqrt(B) - sqrt(A)| <= 1 exactly when (B - A - 1)^2 <= 4A. The golden twin is
// ArcRadiusCheck (sc_model/golden/arc_radius_check.h); the exact formula is
// arc_end_on_circle().
// Idea: bit-serial arithmetic, the 1960s way. The check has the whole reading of the next
// block to finish, so it runs on a one-bit full adder and circulating shift registers
// instead of a 2W + 4-bit adder and its operand multiplexers. A pass is L = 2W + 4 clocks:
// the accumulator goes once round through the adder, LSB first, and is back in place. Pass
// b of a square adds v * v[b] << b: at clock i of the pass the addend bit is
// v[b] & v[i - b] (0 outside v). So every product is a sum of shifted copies, and the
// multiplicands (the held block's magnitudes, from arc_geometry) are read one bit per clock.
// Schedule ((5W + 4) passes of 2W + 4 clocks after start_i; 3024 clocks at W = 16):
//   SumA  2W passes  acc += x0 x0[b] << b, b = 0 .. W-1, then acc += y0 y0[b] << b: acc = A
//   Copy  1 pass     a = acc, acc = ~acc = -A - 1
//   SumB  2W passes  the same with x1, y1: acc = B - A - 1 = E (two's complement)
//   Abs   1 pass     |E| = E, or ~E + 1 if E < 0 (the sign is acc's top bit at the pass
//                    start); e = its low W + 2 bits, far = any higher bit; acc cleared
//   Sq    W+2 passes acc += e e[b] << b: acc = |E|^2; each pass also compares acc <= 4A
//                    LSB first (4A's bit i is a's bit i - 2), the last pass's verdict counts
//   Done             ok_o = !far && acc <= 4A (|E| >= 2^(W+2) fails: 4A < 2^(2W+3))
// The operands must stay constant from the start edge to done (the decoder's held block).
// Until 25 November 2026 (third session) the check ran on one 2W + 4-bit adder in 5W + 5
// clocks (docs/bit-widths.md section 6 has both areas).
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

  localparam int SqWidth    = 2 * IncWidth + 4;  // L: E (signed), |E|^2 < 2^(2W+4), 4A
  localparam int EWidth     = IncWidth + 2;      // |E| when it can pass
  localparam int BitWidth   = $clog2(SqWidth);   // i, the clock within a pass
  localparam int PassWidth  = $clog2(EWidth);    // b, the pass within a square
  localparam logic [BitWidth-1:0]  LastBit    = BitWidth'(SqWidth - 1);
  localparam logic [PassWidth-1:0] LastSumPass = PassWidth'(IncWidth - 1);
  localparam logic [PassWidth-1:0] LastSqPass  = PassWidth'(EWidth - 1);

  typedef enum logic [2:0] {SumA, Copy, SumB, Abs, Sq, Done} phase_e;

  // phase_q, pass_q (b), bit_q (i): where the schedule is; second_q: the y term of a sum of
  // squares. acc_q: the accumulator, circulating (bit i of the word is at acc_q[0] at clock
  // i of a pass); carry_q: the serial adder's carry. a_q: A, circulating with acc_q in the
  // passes that read it. e_q: |E|. far_q: |E| >= 2^(W+2). neg_q: E < 0 (in Abs). le_q: the
  // low bits of acc so far are <= those of 4A (in Sq).
  phase_e                 phase_q;
  logic [PassWidth-1:0]   pass_q;
  logic [BitWidth-1:0]    bit_q;
  logic                   second_q;
  logic [SqWidth-1:0]     acc_q, a_q;
  logic                   carry_q;
  logic [EWidth-1:0]      e_q;
  logic                   far_q, neg_q, le_q;

  // The serial adder: sum = (acc bit ^ invert) + addend + carry in (carry_in0 at a pass's
  // first clock).
  logic                  active, first_bit, last_bit, invert, carry_in0, addend, cin, sum, cout;
  logic                  neg, four_a_bit, le_d;
  logic [IncWidth-1:0]   v;        // the squared operand of a sum pass
  logic [EWidth-1:0]     u;        // ... widened, or e in Sq
  logic [BitWidth-1:0]   offset;   // i - b: the bit of u that pass b adds at clock i
  logic                  in_range; // 0 <= i - b < W + 2

  // The registers change only at the start and while the check runs; the other clocks
  // evaluate nothing here (a fast verilated model).
  assign active    = start_i || phase_q != Done;
  assign first_bit = bit_q == '0;
  assign last_bit  = bit_q == LastBit;

  always_comb begin
    // Used only while the check runs: don't-care ('x) otherwise.
    {v, u, offset, in_range, invert, carry_in0, addend, neg, cin, sum, cout, four_a_bit,
     le_d} = 'x;
    if (active && !start_i) begin
      v = phase_q == SumA ? (second_q ? y0_i : x0_i) : (second_q ? y1_i : x1_i);
      u = phase_q == Sq ? e_q : {2'b00, v};
      offset   = bit_q - BitWidth'(pass_q);
      in_range = bit_q >= BitWidth'(pass_q) && offset < BitWidth'(EWidth);
      neg       = first_bit ? acc_q[SqWidth-1] : neg_q;  // E's sign, read at the pass start
      invert    = phase_q == Copy || (phase_q == Abs && neg);
      carry_in0 = phase_q == Abs && neg;
      addend    = (phase_q == SumA || phase_q == SumB || phase_q == Sq) && u[pass_q] &&
                  in_range && u[offset[PassWidth-1:0]];
      cin       = first_bit ? carry_in0 : carry_q;
      {cout, sum} = {1'b0, acc_q[0] ^ invert} + {1'b0, addend} + {1'b0, cin};
      // acc <= 4A, LSB first: the bit of 4A at clock i is A's bit i - 2, two places behind
      // acc's in a_q (0 at i < 2: A < 2^(2W+1) leaves a's top bits 0).
      four_a_bit = a_q[SqWidth-2];
      le_d = (!sum && four_a_bit) || (sum == four_a_bit && (first_bit || le_q));
    end
  end

  always_ff @(posedge clk_i) begin
    if (!rst_ni) begin
      phase_q  <= Done;
      pass_q   <= '0;
      bit_q    <= '0;
      second_q <= 1'b0;
      acc_q    <= '0;
      a_q      <= '0;
      carry_q  <= 1'b0;
      e_q      <= '0;
      far_q    <= 1'b0;
      neg_q    <= 1'b0;
      le_q     <= 1'b0;
    end else if (start_i) begin
      phase_q  <= SumA;
      pass_q   <= '0;
      bit_q    <= '0;
      second_q <= 1'b0;
      acc_q    <= '0;
      far_q    <= 1'b0;
    end else if (active) begin
      // Every clock: one bit through the adder, the accumulator one place round.
      bit_q   <= last_bit ? '0 : bit_q + 1'b1;
      carry_q <= cout;
      acc_q   <= {sum, acc_q[SqWidth-1:1]};
      unique case (phase_q)
        SumA, SumB: begin
          if (last_bit) begin
            pass_q <= pass_q + 1'b1;
            if (pass_q == LastSumPass) begin
              pass_q   <= '0;
              second_q <= !second_q;
              if (second_q) phase_q <= phase_q == SumA ? Copy : Abs;
            end
          end
        end
        Copy: begin
          a_q <= {acc_q[0], a_q[SqWidth-1:1]};
          if (last_bit) phase_q <= SumB;
        end
        Abs: begin
          neg_q <= neg;
          acc_q <= {1'b0, acc_q[SqWidth-1:1]};
          if (bit_q < BitWidth'(EWidth)) e_q <= {sum, e_q[EWidth-1:1]};
          else far_q <= far_q | sum;
          if (last_bit) phase_q <= Sq;
        end
        Sq: begin
          a_q  <= {a_q[0], a_q[SqWidth-1:1]};
          le_q <= le_d;
          if (last_bit) begin
            pass_q <= pass_q + 1'b1;
            if (pass_q == LastSqPass) phase_q <= Done;
          end
        end
        default: ;
      endcase
    end
  end

  assign done_o = phase_q == Done;
  assign ok_o   = !far_q && le_q;

endmodule
