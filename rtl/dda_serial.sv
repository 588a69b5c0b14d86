// Bit-serial DDA: the circle DDA of rtl/dda_circle.sv (quadrant arcs, and lines as the case
// where the integrands do not move) on three one-bit full adders, one bit per clock.
//
// What: the same integers, the same half-step order (X Y | Y X | X Y ...) and the same
// steps as dda_circle.sv (docs/circle-dda.md), so a block plays the same pulses and the
// same number of iterations; an iteration takes 2P clocks instead of one (P = the pass
// length below). With interp_top's BitSerial it is both the player's DDA and the arc's dry
// run in the decoder (arc_prepare.sv), which counts the iterations N for S = F * N. The
// golden twin is SerialDda (sc_model/golden/dda_serial.h).
// Idea: registers that are read one bit at a time need no logic cells. The six W-bit
// registers (acc, mag, cnt of X and Y) are one P x 6-bit memory, bit i of each at address
// i (a block RAM on the iCE40), read LSB first and written back as they pass: the 1960s
// serial machine, the memory standing in for its delay line.
// Schedule: an iteration is two passes of P = 2^ceil(log2 W) clocks; at clock i of a pass
// bit i of every register goes through an adder or straight back (the memory's registered
// read, addressed at clock i - 1, gives bit i). Pass p integrates axis C (X, Y, Y, X by
// p mod 4); pass p also applies the step that pass p - 1 decided, to that pass's axis U:
// mag_U +- 1 and cnt_U - 1 on the two other adders, whose bits feed C's addend in the same
// clock, so the second half-step sees the magnitude the first one moved. Every value is
// < 2^k, so at clock k - 1 of a pass the half-step is known: the integrator's carry out is
// C's step (a pulse, if C has pulses left), and once the other axis has none, addend bit
// k - 1 is forced on (the finishing rule). At the end of an iteration's second pass both
// counts after its steps are known (the first axis's from its adder, the second's from
// "was 0" and "was 1" flags and its step), so the block's end is known when its last
// iteration ends. A line integrates both axes in the first pass (acc_X on the acc adder,
// acc_Y on the mag adder: its magnitudes never move) and counts its 2^k iterations down in
// cnt_X's place; the second pass leaves its words as they are.
// Timing: load_i takes the block's k, line, growth and directions at an edge; its words
// come bit by bit in the block's first pass, bit bit_o of each on the *_bit_i inputs in
// that clock: the player's multiplexers pick them from the buffered block (interp_top.sv),
// which must hold until words_o falls; the dry run's come from the decoder's words, which
// turn (arc_prepare.sv). An iteration starts
// at an edge with strobe_i when the DDA is idle and the block not done (iterate_o): that
// edge is clock 0 of its first pass; its pulses show after edge k - 1 (a line) or
// P + k - 1 (an arc), and the iteration ends at edge 2P - 1, after which done_o is high if
// it was the block's last. A strobe while an iteration runs is ignored: the feed generator
// never sends one then (feed_generator.sv, LeadBits).
module dda_serial #(
  parameter int IncWidth   = 16,   // >= 2
  parameter int KWidth     = $clog2(IncWidth + 1),
  // Arcs can be loaded (interp_top's CircleMode); without, every block is a line and the
  // arc logic is not built.
  parameter bit CircleMode = 1'b1
) (
  input  logic                clk_i,
  input  logic                rst_ni,
  input  logic                load_i,     // a block loads at this edge
  input  logic                line_i,     // the loading block is a line (else an arc)
  input  logic [KWidth-1:0]   k_i,
  // The block's words, one bit per clock in its first pass: bit bit_o (0 from bit
  // IncWidth on) of |x| and |y| of the start relative to the centre (arc), |dx| and |dy|
  // (the X and Y pulses of the block).
  input  logic                x_bit_i,
  input  logic                y_bit_i,
  input  logic                cnt_x_bit_i,
  input  logic                cnt_y_bit_i,
  output logic [$clog2(IncWidth)-1:0] bit_o,
  input  logic                grow_x_i,   // |x| grows along the arc (arc)
  input  logic                grow_y_i,
  input  logic                dir_x_i,    // 1 = plus
  input  logic                dir_y_i,
  input  logic                strobe_i,   // start an iteration (if idle and not done)
  // The machine has stopped (interp_top's E-stop or a limit): an iteration in flight emits
  // no more pulses, so no pulse comes after the stop's clock and the counters stay true.
  input  logic                mute_i,
  output logic                iterate_o,  // an iteration starts at this edge
  output logic                carry_x_o,  // pulses emitted at this edge (for the counters)
  output logic                carry_y_o,
  output logic                step_x_o,
  output logic                dir_x_o,
  output logic                step_y_o,
  output logic                dir_y_o,
  output logic                words_o,    // the loaded block's words are still to be read
  output logic                done_o      // the block's iterations are over
);

  localparam int BitWidth = $clog2(IncWidth);
  localparam int PassLength = 1 << BitWidth;
  // Bit indexes and k compared in BitWidth + 1 bits (>= KWidth): i + 1 can be P.
  localparam int IdxWidth = BitWidth + 1;
  localparam logic [BitWidth-1:0] LastBit = BitWidth'(PassLength - 1);

  // bits: the registers, bit i of each at address i (A word: bit i of each register, at
  // these places; a line keeps its iterations left, 2^k - 1 - j, in CntX's place).
  localparam int AccX = 5, AccY = 4, MagX = 3, MagY = 2, CntX = 1, CntY = 0;
  (* no_rw_check *) logic [5:0] bits [PassLength];  // never read and written at one address
  logic [5:0]          read_q, cur, next;
  // The block: k, line, growth, directions (held for the block; its words are in bits).
  logic [KWidth-1:0]   k_q;
  logic                line_q, grow_x_q, grow_y_q, dir_x_q, dir_y_q;
  // run_q: an iteration's passes are running; words_q: the pass to come or running is the
  // block's first (it reads the words); half_q: the pass's place in X Y Y X (C is Y at 1
  // and 2; U, the previous pass's axis, is Y at 2 and 3; bit 0: an iteration's second
  // pass); bit_q: i. pend_q: the previous pass's step, applied in this pass; step_q: this
  // pass's step (from clock k - 1). carry_*_q: the serial adders' carries. zero_*_q /
  // one_*_q: that axis's count is 0 / 1 (as of its last update); zrun_q / orun_q: U's
  // updated count is 0 / 1 in the bits so far. last_q: a line's last iteration runs.
  logic                run_q, words_q, done_q, last_q;
  logic [1:0]          half_q;
  logic [BitWidth-1:0] bit_q, next_bit;
  logic                pend_q, step_q, carry_acc_q, carry_mag_q, carry_cnt_q;
  logic                zero_x_q, zero_y_q, one_x_q, one_y_q, zrun_q, orun_q;
  // yzero_q / yone_q: in the block's first pass, |dy| is 0 / 1 in the bits so far (its
  // flags are made from its bits as they come: every count is < 2^k, so they are final
  // by clock k - 1, where the first pass needs Y's zero flag).
  logic                yzero_q, yone_q;
  logic                step_x_q, step_y_q;

  // line: the loaded block is a line (always, without circle mode).
  logic                line, active, first_bit, top_bit, below_k, pass_end, second;
  logic                c_is_y, u_is_y, u_grow, u_mag, u_cnt, c_acc, o_mag, o_zero, c_zero;
  logic                mag_add, mag_b, mag_sum, mag_cout, cnt_b, cnt_sum, cnt_cout;
  logic                zrun_d, orun_d, addend, acc_sum, acc_cout, acc_bit, step, pass_step;
  logic                g_zero, g_one, yzero_d, yone_d;

  assign line      = !CircleMode || line_q;
  assign iterate_o = strobe_i && !run_q && !done_q && !load_i;
  assign active    = !load_i && (run_q || iterate_o);
  assign first_bit = bit_q == '0;
  assign pass_end  = bit_q == LastBit;
  assign second    = half_q[0];
  assign c_is_y    = half_q[1] ^ half_q[0];
  assign u_is_y    = half_q[1];
  // Clock k - 1 of the pass, and the bits below k (the integrators').
  assign top_bit   = {1'b0, bit_q} + 1'b1 == IdxWidth'(k_q);
  assign below_k   = {1'b0, bit_q} < IdxWidth'(k_q);
  assign next_bit  = bit_q + 1'b1;  // wraps at the pass's end

  // Bit i of each register: the memory's, or in the block's first pass its words. acc
  // starts at 2^(k-1) (rounding to nearest), whose bit i is 1 at i = k - 1 only; a line's
  // magnitude places hold the other axis's |d| (each integrator adds the other place, as
  // in dda_circle.sv) and its iterations left start at 2^k - 1 (the bits below k).
  always_comb begin
    cur = read_q;
    if (words_q) begin
      cur[AccX] = top_bit;
      cur[AccY] = top_bit;
      cur[MagX] = line ? cnt_y_bit_i : x_bit_i;
      cur[MagY] = line ? cnt_x_bit_i : y_bit_i;
      cur[CntX] = line ? below_k : cnt_x_bit_i;
      cur[CntY] = cnt_y_bit_i;
    end
  end

  // A count is 0 / 1 in its bits so far, LSB first ({zero, one} after this bit): for U's
  // count as its adder forms it, and for |dy| as it comes in the first pass.
  function automatic logic [1:0] zero_one(input logic first, input logic zero_q,
                                          input logic one_q, input logic b);
    zero_one = {(first || zero_q) && !b, first ? b : one_q && !b};
  endfunction

  always_comb begin
    // Used only while running: don't-care ('x) otherwise (no gates, no evaluation).
    {u_grow, u_mag, u_cnt, c_acc, o_mag, o_zero, c_zero, mag_add, mag_b, mag_sum, mag_cout,
     cnt_b, cnt_sum, cnt_cout, zrun_d, orun_d, yzero_d, yone_d, addend, acc_sum, acc_cout,
     acc_bit, step, pass_step, g_zero, g_one} = 'x;
    if (active) begin
      // The mag adder: an arc's U update, mag + 1 or + all ones (- 1) when pend; a line's
      // Y integrator, acc_Y + |dy| (in MagX's place). The cnt adder: an arc's cnt_U - pend;
      // a line's iterations left - 1. A line's passes have U = X.
      u_grow  = u_is_y ? grow_y_q : grow_x_q;
      u_mag   = u_is_y ? cur[MagY] : cur[MagX];
      u_cnt   = u_is_y ? cur[CntY] : cur[CntX];
      mag_add = pend_q && (first_bit || !u_grow);
      mag_b   = line ? cur[AccY] : mag_add;
      cnt_b   = line || pend_q;
      {mag_cout, mag_sum} = {1'b0, u_mag} + {1'b0, mag_b} + {1'b0, !first_bit && carry_mag_q};
      {cnt_cout, cnt_sum} = {1'b0, u_cnt} + {1'b0, cnt_b} + {1'b0, !first_bit && carry_cnt_q};
      {zrun_d, orun_d}  = zero_one(first_bit, zrun_q, orun_q, cnt_sum);
      {yzero_d, yone_d} = zero_one(first_bit, yzero_q, yone_q, cur[CntY]);
      // C's half-step: acc_C + |O| (O = the other axis: U itself within an iteration, so
      // its moved magnitude), bit k - 1 forced on once O has no pulses left (arcs only).
      c_acc   = c_is_y ? cur[AccY] : cur[AccX];
      if (c_is_y != u_is_y) begin
        o_mag  = mag_sum;
        o_zero = zrun_d;
        c_zero = c_is_y ? zero_y_q : zero_x_q;
      end else begin
        o_mag  = c_is_y ? cur[MagX] : cur[MagY];
        o_zero = c_is_y ? zero_x_q : (words_q ? yzero_d : zero_y_q);
        c_zero = zrun_d;
      end
      addend  = o_mag || (top_bit && o_zero && !line);
      {acc_cout, acc_sum} = {1'b0, c_acc} + {1'b0, addend} + {1'b0, !first_bit && carry_acc_q};
      acc_bit = below_k && acc_sum;  // clearing bit k subtracts 2^k
      step    = acc_cout && !c_zero;
      // This pass's step, final from clock k - 1 on; an arc's second axis G (C of the
      // second pass) ends with a count of 0 if it was 0, or 1 and steps now.
      pass_step = top_bit ? step : step_q;
      g_zero  = c_is_y ? zero_y_q : zero_x_q;
      g_one   = c_is_y ? one_y_q : one_x_q;
    end
  end

  // The pulses of an iteration, together at one clock as the one-clock DDA gives them (a
  // pulse path with the first axis's step alone would pass through corners that DDA never
  // shows, up to 0.02 BLU further from an arc than its bound): a line's at clock k - 1 of
  // its first pass; an arc's at clock k - 1 of its second pass, where C is its second axis
  // and pend_q holds the first axis's step.
  always_comb begin
    carry_x_o = 1'b0;
    carry_y_o = 1'b0;
    if (active && top_bit && !mute_i) begin
      if (line) begin
        carry_x_o = !second && acc_cout;
        carry_y_o = !second && mag_cout;
      end else if (second) begin
        carry_x_o = c_is_y ? pend_q : step;
        carry_y_o = c_is_y ? step : pend_q;
      end
    end
  end

  // What clock i writes back at address i: an arc's acc of C and mag, cnt of U; a line's
  // acc_X, acc_Y and iterations left in its first pass; the others unchanged.
  always_comb begin
    next = cur;
    if (line) begin
      if (!second) begin
        next[AccX] = acc_bit;
        next[AccY] = below_k && mag_sum;
        next[CntX] = cnt_sum;
      end
    end else begin
      if (c_is_y) next[AccY] = acc_bit;
      else        next[AccX] = acc_bit;
      if (u_is_y) {next[MagY], next[CntY]} = {mag_sum, cnt_sum};
      else        {next[MagX], next[CntX]} = {mag_sum, cnt_sum};
    end
  end

  // The memory: one write and one read per running clock, no reset (the block's first
  // pass reads its words instead).
  always_ff @(posedge clk_i) begin
    if (active) begin
      bits[bit_q] <= next;
      read_q      <= bits[next_bit];
    end
  end

  always_ff @(posedge clk_i) begin
    if (!rst_ni) begin
      k_q <= '0;
      {line_q, grow_x_q, grow_y_q, dir_x_q, dir_y_q} <= '0;
      {run_q, words_q, last_q} <= '0;
      done_q <= 1'b1;  // no block: done, as dda_circle after reset
      half_q <= '0;
      bit_q  <= '0;
      {pend_q, step_q, carry_acc_q, carry_mag_q, carry_cnt_q} <= '0;
      {zero_x_q, zero_y_q, one_x_q, one_y_q, zrun_q, orun_q, yzero_q, yone_q} <= '0;
      {step_x_q, step_y_q} <= '0;
    end else begin
      step_x_q <= carry_x_o;
      step_y_q <= carry_y_o;
      if (load_i) begin
        k_q      <= k_i;
        line_q   <= line_i;
        grow_x_q <= grow_x_i;
        grow_y_q <= grow_y_i;
        dir_x_q  <= dir_x_i;
        dir_y_q  <= dir_y_i;
        // X's and Y's flags are made in the first pass (X is its U; Y's from its bits).
        {run_q, done_q, pend_q} <= '0;
        words_q  <= 1'b1;
        half_q   <= '0;
        bit_q    <= '0;
      end else if (active) begin
        run_q       <= 1'b1;
        carry_acc_q <= acc_cout;
        carry_mag_q <= mag_cout;
        carry_cnt_q <= cnt_cout;
        zrun_q      <= zrun_d;
        orun_q      <= orun_d;
        yzero_q     <= yzero_d;
        yone_q      <= yone_d;
        if (top_bit) step_q <= step;
        if (pass_end) begin
          words_q <= 1'b0;
          // A line's passes keep U = X (half 0, 1); an arc's go round X Y Y X.
          half_q  <= {half_q[1] ^ (half_q[0] && !line), !half_q[0]};
          pend_q  <= pass_step;
          if (u_is_y) {zero_y_q, one_y_q} <= {zrun_d, orun_d};
          else        {zero_x_q, one_x_q} <= {zrun_d, orun_d};
          if (words_q) {zero_y_q, one_y_q} <= {yzero_d, yone_d};
          // A line's iterations left were 0 if - 1 did not carry out.
          if (!second) last_q <= !cnt_cout;
          if (second) begin
            run_q  <= 1'b0;
            done_q <= line ? last_q : zrun_d && (g_zero || g_one && pass_step);
          end
        end
        bit_q <= next_bit;
      end
    end
  end

  assign step_x_o = step_x_q;
  assign step_y_o = step_y_q;
  assign dir_x_o  = dir_x_q;
  assign dir_y_o  = dir_y_q;
  assign words_o  = words_q;
  assign bit_o    = bit_q;
  assign done_o   = done_q;

`ifndef SYNTHESIS
  // The invariant the schedule relies on, checked at every running clock of every
  // verilated run (Verilator --assert) and in every formal proof that reads this module:
  // every value is below 2^k, so all its bits from k on are 0 and a half-step is known at
  // clock k - 1 of its pass. (A line's iterations left wrap below 0 in its last iteration,
  // which ends the block: that count is not held to it.)
  always_ff @(posedge clk_i) begin
    if (rst_ni && active && !below_k) begin
      a_below_2k: assert ((cur & ~(line ? 6'(1 << CntX) : 6'b0)) == '0);
    end
  end
`endif

endmodule
