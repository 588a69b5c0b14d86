// Dry run of an arc's circle DDA, bit-serial: counts the block's iterations N, no pulses.
//
// What: the decoder needs N before it hands an arc on (S = F * N, arc_prepare.sv). This
// module plays the arc's circle DDA (rtl/dda_circle.sv, docs/circle-dda.md) once, with the
// same integers and the same half-step order (X Y | Y X | X Y ...), and marks each
// iteration (iterate_o). The golden twin is ArcDryRun (sc_model/golden/arc_dry_run.h).
// Idea: the player's DDA must make an iteration per clock; the dry run only has to be over
// before the block is needed, so it runs serially, the 1960s way: six circulating
// registers (acc, mag, cnt of X and Y) and three one-bit full adders instead of six W-bit
// adders. Every value is < 2^k (k = the arc's bit length, at most W), LSB first. The six
// registers are one W x 6-bit memory, bit i of each at address i (`bits`): a block RAM on
// the iCE40 (one SB_RAM40_4K of the HX1K's 16), so their 6W bits need no logic cells.
// Schedule: a pass is W clocks, one half-step; clock i of a pass reads bit i of every
// register (the memory's registered read, addressed at clock i - 1) and writes it back, new
// or unchanged, at address i. The first pass after the start reads the arc's words instead
// (the memory still holds the previous arc): x_i[i], y_i[i], cnt_*_i[i], and acc = 2^(k-1).
// Pass p integrates axis C (X, Y, Y, X, X, Y, ... by p mod 4). Pass p also applies the
// step that pass p - 1 decided, on that pass's axis U: mag_U +- step and cnt_U - step, on
// two serial adders whose result bits feed C's addend in the same clock. So the second half-step of an iteration sees
// the magnitude the first one just moved (the semi-implicit update), with no extra pass.
// At clock k - 1 of a pass everything of that half-step is known (bits >= k are 0): the
// carry out of the integrator is the step (if C has pulses left after U's update), and the
// "other axis finished" rule forces addend bit k - 1 on. An even pass starts an
// iteration: at its clock k - 1, both counts are final, so if both are 0 the dry run is
// done (done_o from the next clock), else the iteration is counted (iterate_o).
// Timing: start_i loads the arc at an edge; iteration j (from 0) is marked at edge 2jW + k
// after it, and done_o rises after edge 2NW + k. run_i low stops it (a failed radius check);
// the inputs must stay constant from the start edge while it runs (the decoder's held
// block). interp_top's BitSerial chooses it (the board does); the default dry run is a
// second dda_circle, one iteration per clock (docs/bit-widths.md section 6 has both areas).
module arc_dry_run #(
  parameter int IncWidth = 16,
  parameter int KWidth   = $clog2(IncWidth + 1)
) (
  input  logic                clk_i,
  input  logic                rst_ni,
  input  logic                start_i,    // load the arc at this edge
  input  logic                run_i,      // the preparation goes on (after the start edge)
  input  logic [KWidth-1:0]   k_i,        // the modulus 2^k (arc_geometry.sv), k >= 1
  input  logic [IncWidth-1:0] x_i,        // |x0|, |y0| relative to the centre
  input  logic [IncWidth-1:0] y_i,
  input  logic [IncWidth-1:0] cnt_x_i,    // |dx|, |dy|: the pulses of each axis
  input  logic [IncWidth-1:0] cnt_y_i,
  input  logic                grow_x_i,   // |x| grows at X's steps
  input  logic                grow_y_i,
  output logic                iterate_o,  // an iteration is counted at this edge
  output logic                done_o      // all N iterations are counted
);

  localparam int BitWidth = $clog2(IncWidth);
  localparam logic [BitWidth-1:0] LastBit = BitWidth'(IncWidth - 1);

  // bits: the registers, bit i of each at address i; cur: bit i of each at clock i (read_q,
  // the memory's read, or the arc's words in the first pass: first_pass_q); next: what
  // clock i writes back.
  // half_q: the pass's place in X Y Y X (C is Y at 1 and 2; U, the previous pass's axis,
  // is Y at 2 and 3). bit_q: i. pend_q: pass p - 1's step, applied in this pass; step_q:
  // this pass's step (from clock k - 1). carry_*_q: the serial adders' carries. zero_*_q:
  // that axis has no pulses left (for U, before this pass's update); zrun_q: U's updated
  // count is 0 in the bits so far. busy_q: between the start edge and done.
  // A word of the memory: bit i of each register, at these places.
  localparam int AccX = 5, AccY = 4, MagX = 3, MagY = 2, CntX = 1, CntY = 0;
  (* no_rw_check *) logic [5:0] bits [IncWidth];  // never read and written at one address
  logic [5:0]          read_q, cur, next;
  logic [BitWidth-1:0] next_bit;
  logic                first_pass_q;
  logic [1:0]          half_q;
  logic [BitWidth-1:0] bit_q;
  logic                pend_q, step_q, carry_acc_q, carry_mag_q, carry_cnt_q;
  logic                zero_x_q, zero_y_q, zrun_q, busy_q, done_q;

  logic                active, first_bit, top_bit, below_k;
  logic                c_is_y, u_is_y, u_grow, u_mag, u_cnt, c_acc, o_mag, o_zero, c_zero;
  logic                mag_add, mag_sum, mag_cout, cnt_sum, cnt_cout, zrun_d, u_zero;
  logic                addend, acc_sum, acc_cout, acc_bit, step, check, finished;

  assign active    = start_i || (run_i && busy_q);
  assign first_bit = bit_q == '0;
  assign c_is_y    = half_q[1] ^ half_q[0];
  assign u_is_y    = half_q[1];
  // Clock k - 1 of the pass, and the bits below k (the integrator's).
  assign top_bit   = KWidth'(bit_q) + 1'b1 == k_i;
  assign below_k   = KWidth'(bit_q) < k_i;
  assign next_bit  = bit_q == LastBit ? '0 : bit_q + 1'b1;
  // Bit i of each register; acc starts at 2^(k-1) (rounding to nearest, as the player's DDA
  // loads), whose bit i is 1 at i = k - 1 only.
  assign cur = first_pass_q ? {top_bit, top_bit, x_i[bit_q], y_i[bit_q],  // AccX .. CntY
                               cnt_x_i[bit_q], cnt_y_i[bit_q]}
                            : read_q;

  always_comb begin
    // Used only while running: don't-care ('x) otherwise (no gates, no evaluation).
    {u_grow, u_mag, u_cnt, c_acc, o_mag, o_zero, c_zero, mag_add, mag_sum, mag_cout,
     cnt_sum, cnt_cout, zrun_d, u_zero, addend, acc_sum, acc_cout, acc_bit, step,
     check, finished} = 'x;
    if (active && !start_i) begin
      // U's update: mag + 1, or + all ones (- 1), when pend; cnt + all ones (- 1).
      u_grow  = u_is_y ? grow_y_i : grow_x_i;
      u_mag   = u_is_y ? cur[MagY] : cur[MagX];
      u_cnt   = u_is_y ? cur[CntY] : cur[CntX];
      mag_add = pend_q && (first_bit || !u_grow);
      {mag_cout, mag_sum} = {1'b0, u_mag} + {1'b0, mag_add} + {1'b0, !first_bit && carry_mag_q};
      {cnt_cout, cnt_sum} = {1'b0, u_cnt} + {1'b0, pend_q} + {1'b0, !first_bit && carry_cnt_q};
      zrun_d  = (first_bit || zrun_q) && !cnt_sum;
      u_zero  = zrun_d;  // U's updated count is 0 (final at clock k - 1: cnt < 2^k)
      // C's half-step: acc_C + |O| (O = the other axis: U itself within an iteration, so
      // its moved magnitude), with bit k - 1 forced on once O has no pulses left.
      c_acc   = c_is_y ? cur[AccY] : cur[AccX];
      if (c_is_y != u_is_y) begin
        o_mag  = mag_sum;
        o_zero = u_zero;
        c_zero = c_is_y ? zero_y_q : zero_x_q;
      end else begin
        o_mag  = c_is_y ? cur[MagX] : cur[MagY];
        o_zero = c_is_y ? zero_x_q : zero_y_q;
        c_zero = u_zero;
      end
      addend  = o_mag || (top_bit && o_zero);
      {acc_cout, acc_sum} = {1'b0, c_acc} + {1'b0, addend} + {1'b0, !first_bit && carry_acc_q};
      acc_bit = below_k && acc_sum;  // clearing bit k subtracts 2^k
      step    = acc_cout && !c_zero;
      // An even pass starts an iteration (U = C there): at clock k - 1, are both counts 0?
      check    = top_bit && !half_q[0];
      finished = check && u_zero && o_zero;
    end
  end

  assign done_o    = done_q;
  assign iterate_o = active && !start_i && check && !finished;

  // What clock i writes back at address i: the adders' bits on the registers this pass
  // writes (acc of C; mag and cnt of U), the others unchanged.
  always_comb begin
    next = cur;
    if (c_is_y) next[AccY] = acc_bit;
    else        next[AccX] = acc_bit;
    if (u_is_y) {next[MagY], next[CntY]} = {mag_sum, cnt_sum};
    else        {next[MagX], next[CntX]} = {mag_sum, cnt_sum};
  end

  // The memory: one write and one read per running clock, no reset (the first pass does
  // not read it).
  always_ff @(posedge clk_i) begin
    if (active && !start_i) begin
      bits[bit_q] <= next;
      read_q      <= bits[next_bit];
    end
  end

  always_ff @(posedge clk_i) begin
    if (!rst_ni) begin
      first_pass_q <= 1'b0;
      half_q <= '0;
      bit_q  <= '0;
      {pend_q, step_q, carry_acc_q, carry_mag_q, carry_cnt_q} <= '0;
      {zero_x_q, zero_y_q, zrun_q, busy_q, done_q} <= '0;
    end else if (start_i) begin
      first_pass_q <= 1'b1;
      zero_x_q <= cnt_x_i == '0;
      zero_y_q <= cnt_y_i == '0;
      half_q   <= '0;
      bit_q    <= '0;
      pend_q   <= 1'b0;
      busy_q   <= 1'b1;
      done_q   <= 1'b0;
    end else if (active) begin
      carry_acc_q <= acc_cout;
      carry_mag_q <= mag_cout;
      carry_cnt_q <= cnt_cout;
      zrun_q      <= zrun_d;
      if (top_bit) step_q <= step;
      if (finished) begin
        busy_q <= 1'b0;
        done_q <= 1'b1;
      end
      if (bit_q == LastBit) begin
        first_pass_q <= 1'b0;
        half_q <= half_q + 1'b1;
        pend_q <= top_bit ? step : step_q;
        if (u_is_y) zero_y_q <= zrun_d;
        else        zero_x_q <= zrun_d;
      end
      bit_q <= next_bit;
    end
  end

endmodule
