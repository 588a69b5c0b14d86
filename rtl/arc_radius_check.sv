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
// operands are read one bit per clock with no multiplexer: in pass b the decoder's words
// (|I| = x0, |J| = y0, |X|, |Y|) turn one place at each of the clocks b .. b + W - 1
// (shift_o), so bit 0 shows v[i - b] there and they are back in place at the pass's end;
// x1 = x0 +- |X| and y1 come from a serial adder on those bits (add_*_i: the geometry's
// sum or difference), restarted at clock b; |E| turns in e_q the same way in Sq (clocks
// b .. b + W + 1). The multiplier bit v[b] is caught the pass before, at its clock 2b - 1
// where v[b] passes (mul_next_q), and for pass 0 at clock 0 (mul_q).
// Schedule ((5W + 4) passes of 2W + 4 clocks after start_i; 3024 clocks at W = 16):
//   SumA  2W passes  acc += x0 x0[b] << b, b = 0 .. W-1, then acc += y0 y0[b] << b: acc = A
//   Copy  1 pass     a = acc, acc = ~acc = -A - 1
//   SumB  2W passes  the same with x1, y1: acc = B - A - 1 = E (two's complement)
//   Abs   1 pass     |E| = E, or ~E + 1 if E < 0 (the sign is acc's top bit at the pass
//                    start); e = its low W + 2 bits, far = any higher bit; acc cleared
//   Sq    W+2 passes acc += e e[b] << b: acc = |E|^2; each pass also compares acc <= 4A
//                    LSB first (4A's bit i is a's bit i - 2), the last pass's verdict counts
//   Done             ok_o = !far && acc <= 4A (|E| >= 2^(W+2) fails: 4A < 2^(2W+3))
// The words must hold from the start edge to done but for the turns (the decoder's held
// block); the dry run (arc_prepare.sv) reads its first pass from the same turns (pass 0).
// The two circulating registers, acc and 4A, are one L x 2-bit memory, bit i of each at
// address i (`bits`; a block RAM on the iCE40, so their 2L bits need no logic cells):
// clock i of a pass reads bit i (the memory's registered read, addressed at clock i - 1)
// and writes it back, new or unchanged. The first pass reads acc as 0 (the memory still
// holds the previous arc's). 4A is written in Copy, bit i from acc's bit i - 2 (acc2_q).
// Bit-serial rather than on one 2W + 4-bit adder in 5W + 5 clocks: less than half the LUT4s
// for more clocks than any arc above about 1 mm radius takes anyway (docs/area.md).
module arc_radius_check #(
  parameter int IncWidth = 16
) (
  input  logic                clk_i,
  input  logic                rst_ni,
  input  logic                start_i,
  // The words' bits of this clock (bit 0 of the decoder's I, J, X, Y magnitudes, which
  // turn one place at each edge with shift_o), and whether |x1| = |x0| + |dx| (else - |dx|)
  // and |y1| = |y0| + |dy|.
  input  logic                x0_bit_i,
  input  logic                y0_bit_i,
  input  logic                dx_bit_i,
  input  logic                dy_bit_i,
  input  logic                add_x_i,
  input  logic                add_y_i,
  output logic                shift_o,
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
  // squares. bits: the accumulator and 4A, bit i at address i ([Acc], [FourA]); read_q:
  // the word of this clock's bit (cur: as used, acc 0 in the first pass, first_pass_q);
  // next: what this clock writes back. acc2_q: acc's bits of the two clocks before (Copy).
  // carry_q: the serial adder's carry. e_q: |E|. far_q: |E| >= 2^(W+2). neg_q: E < 0
  // (E's top bit, the last bit of SumB; used in Abs). le_q: the low bits of acc so far
  // are <= those of 4A (in Sq).
  localparam int Acc = 1, FourA = 0;
  phase_e                 phase_q;
  logic [PassWidth-1:0]   pass_q;
  logic [BitWidth-1:0]    bit_q, next_bit;
  logic                   second_q, first_pass_q;
  (* no_rw_check *) logic [1:0] bits [SqWidth];  // never read and written at one address
  logic [1:0]             read_q, cur, next, acc2_q;
  logic                   carry_q, end_carry_q, mul_q, mul_next_q;
  logic [EWidth-1:0]      e_q;
  logic                   far_q, neg_q, le_q;

  // The serial adder: sum = (acc bit ^ invert) + addend + carry in (carry_in0 at a pass's
  // first clock).
  logic                  active, first_bit, last_bit, invert, carry_in0, addend, cin, sum, cout;
  logic                  four_a_bit, le_d;
  logic [BitWidth-1:0]   offset;   // i - b: the bit of u that pass b adds at clock i
  logic                  in_range; // 0 <= i - b < W + 2
  logic                  in_word;  // 0 <= i - b < W
  logic                  w_bit, d_bit, add, end_cin, end_sum, end_cout, op_bit, mul;

  // The registers change only at the start and while the check runs; the other clocks
  // evaluate nothing here (a fast verilated model).
  assign active    = start_i || phase_q != Done;
  assign first_bit = bit_q == '0;
  assign last_bit  = bit_q == LastBit;
  assign next_bit  = last_bit ? '0 : bit_q + 1'b1;
  assign cur       = first_pass_q ? {1'b0, read_q[FourA]} : read_q;

  always_comb begin
    // Used only while the check runs: don't-care ('x) otherwise.
    {offset, in_range, invert, carry_in0, addend, cin, sum, cout, four_a_bit,
     le_d, next, w_bit, d_bit, add, end_cin, end_sum, end_cout, op_bit, mul} = 'x;
    in_word = 1'b0;
    if (active && !start_i) begin
      offset   = bit_q - BitWidth'(pass_q);
      in_range = bit_q >= BitWidth'(pass_q) && offset < BitWidth'(EWidth);
      in_word  = bit_q >= BitWidth'(pass_q) && offset < BitWidth'(IncWidth) &&
                 (phase_q == SumA || phase_q == SumB);
      // The operand's bit i - b: x0 or y0 as it comes; x1 or y1 from a serial adder
      // (|x0| + |dx|, or |x0| + ~|dx| + 1), restarted at the window's first clock; |E| from
      // e_q, which turns in its window in Sq.
      w_bit   = second_q ? y0_bit_i : x0_bit_i;
      d_bit   = second_q ? dy_bit_i : dx_bit_i;
      add     = second_q ? add_y_i : add_x_i;
      end_cin = offset == '0 ? !add : end_carry_q;
      {end_cout, end_sum} = {1'b0, w_bit} + {1'b0, d_bit ^ !add} + {1'b0, end_cin};
      op_bit  = phase_q == Sq ? in_range && e_q[0]
                              : in_word && (phase_q == SumA ? w_bit : end_sum);
      // The multiplier bit u[b]: caught by the pass before (at i - b = b + 1), or at pass
      // 0 the operand's bit 0, at its clock 0 and held after.
      mul       = pass_q == '0 && first_bit ? op_bit : mul_q;
      invert    = phase_q == Copy || (phase_q == Abs && neg_q);
      carry_in0 = phase_q == Abs && neg_q;
      addend    = (phase_q == SumA || phase_q == SumB || phase_q == Sq) && mul && op_bit;
      cin       = first_bit ? carry_in0 : carry_q;
      {cout, sum} = {1'b0, cur[Acc] ^ invert} + {1'b0, addend} + {1'b0, cin};
      // acc <= 4A, LSB first (in Sq).
      four_a_bit = cur[FourA];
      le_d = (!sum && four_a_bit) || (sum == four_a_bit && (first_bit || le_q));
      // Written back: acc's new bit (0 in Abs, which clears it), and 4A unchanged, or in
      // Copy A's bit i - 2, two clocks back (at i < 2 that is A's bit L - 2 or L - 1 from
      // the end of SumA, 0: A < 2^(2W+1)).
      next[Acc]   = phase_q == Abs ? 1'b0 : sum;
      next[FourA] = phase_q == Copy ? acc2_q[1] : cur[FourA];
    end
  end

  always_ff @(posedge clk_i) begin
    if (!rst_ni) begin
      phase_q  <= Done;
      pass_q   <= '0;
      bit_q    <= '0;
      second_q <= 1'b0;
      first_pass_q <= 1'b0;
      acc2_q   <= '0;
      carry_q  <= 1'b0;
      end_carry_q <= 1'b0;
      mul_q    <= 1'b0;
      mul_next_q <= 1'b0;
      e_q      <= '0;
      far_q    <= 1'b0;
      neg_q    <= 1'b0;
      le_q     <= 1'b0;
    end else if (start_i) begin
      phase_q  <= SumA;
      pass_q   <= '0;
      bit_q    <= '0;
      second_q <= 1'b0;
      first_pass_q <= 1'b1;  // acc = 0
      far_q    <= 1'b0;
    end else if (active) begin
      // Every clock: one bit through the adder.
      bit_q   <= next_bit;
      carry_q <= cout;
      acc2_q  <= {acc2_q[0], cur[Acc]};
      if (last_bit) first_pass_q <= 1'b0;
      end_carry_q <= end_cout;
      if (pass_q == '0 && first_bit) mul_q <= op_bit;
      if (bit_q == {pass_q, 1'b1}) mul_next_q <= op_bit;  // i - b = b + 1
      if (last_bit) mul_q <= mul_next_q;
      unique case (phase_q)
        SumA, SumB: begin
          // E's sign: its top bit, the last written by SumB.
          if (last_bit) neg_q <= sum;
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
          if (last_bit) phase_q <= SumB;
        end
        Abs: begin
          if (bit_q < BitWidth'(EWidth)) e_q <= {sum, e_q[EWidth-1:1]};
          else far_q <= far_q | sum;
          if (last_bit) phase_q <= Sq;
        end
        Sq: begin
          if (in_range) e_q <= {e_q[0], e_q[EWidth-1:1]};
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

  // The memory: one write and one read per running clock, no reset.
  always_ff @(posedge clk_i) begin
    if (active && !start_i) begin
      bits[bit_q] <= next;
      read_q      <= bits[next_bit];
    end
  end

  assign shift_o = in_word;
  assign done_o = phase_q == Done;
  assign ok_o   = !far_q && le_q;

endmodule
