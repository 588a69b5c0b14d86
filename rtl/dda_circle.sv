// Circle DDA: two cross-coupled integrators with immediate update, which play a quadrant
// arc, and a line as the case where the integrands do not move.
//
// What (docs/circle-dda.md): coordinates are magnitudes relative to the arc's centre. The X
// integrator adds |y| and the Y integrator adds |x| at every iteration (modulus 2^k, k =
// bit length of the largest magnitude on the arc); a carry is a step of that axis and
// moves its magnitude by one BLU. The second half-step of an iteration already sees the
// magnitude the first one moved (semi-implicit: the orbit closes, it does not spiral out
// like forward Euler), and the order alternates every iteration, X first on the first one,
// which cancels the first-order tilt of the closed curve. Per-axis pulse counters (|dx|,
// |dy|) stop each axis exactly at the programmed end; the block's iterations are over
// when both are 0 (done_o). The golden twin is sc_model/golden/dda_circle.h (which keeps
// the axes by name and a y_first flag; here they are kept by role, see below: the same
// values, one multiplexer layer less).
// A line (line_i at the load; method L1 of docs/interpolator.md) runs on the same
// integrators: each adds its own axis's |d| at every iteration for exactly 2^k iterations
// (rem_q), and its carries are the steps. The magnitudes then hold the increments and never
// move; since an integrator adds the other axis's magnitude register, that register holds
// this axis's |d| (mag_x = |dy|, mag_y = |dx|). One pair of integrators for both motions,
// as in the interpolators of the 1960s, instead of a line DDA beside the circle DDA.
// Timing: load_i loads the block at an edge where no iteration happens; an iteration
// happens at an edge with strobe_i while !done_o and its pulses show after that edge.
// The next-state logic is evaluated only at a load, an iteration or to clear the step
// pulses (the registers' enable): most clocks of a part have none, and this keeps the
// verilated model fast.
module dda_circle #(
  parameter int IncWidth   = 16,
  parameter int KWidth     = $clog2(IncWidth + 1),
  // Arcs can be loaded (interp_top's CircleMode); without, every block is a line and the
  // arc logic is not built.
  parameter bit CircleMode = 1'b1
) (
  input  logic                clk_i,
  input  logic                rst_ni,
  // The loading block's geometry (arc_geometry.sv).
  input  logic                load_i,
  input  logic                line_i,     // the loading block is a line (else an arc)
  input  logic [KWidth-1:0]   k_i,
  input  logic [IncWidth-1:0] x_i,        // |x| of the start, relative to the centre (arc)
  input  logic [IncWidth-1:0] y_i,        // |y| of the start (arc)
  input  logic [IncWidth-1:0] cnt_x_i,    // |dx|: X pulses of the block
  input  logic [IncWidth-1:0] cnt_y_i,    // |dy|
  input  logic                grow_x_i,   // |x| grows along the arc (arc)
  input  logic                grow_y_i,
  input  logic                dir_x_i,    // 1 = plus
  input  logic                dir_y_i,
  input  logic                strobe_i,   // one iteration at this edge (ignored when done)
  output logic                carry_x_o,  // pulses emitted at this edge (for the counters)
  output logic                carry_y_o,
  output logic                step_x_o,
  output logic                dir_x_o,
  output logic                step_y_o,
  output logic                dir_y_o,
  output logic                done_o      // both axes have emitted all their pulses
);

  // kpow_q: 2^k of the playing block, one-hot (the integrators' carry bit).
  // The axes are stored by role, not by name: A is the axis that goes first in the next
  // iteration, B the other. The axis that went second goes first in the next iteration
  // (X Y | Y X | X Y ...), so after every iteration A and B simply swap: the first
  // half-step always reads A and the second always B, with no operand multiplexer, and
  // a_is_y_q says which axis A is (it toggles every iteration; X first after a load).
  // acc_*_q: the integrators, in [0, 2^k), half at the load (rounding to nearest).
  // mag_*_q: |a|, |b| relative to the centre. cnt_*_q: pulses left. grow_*_q: the
  // magnitude grows at that axis's steps (fixed for the block).
  // line_q: the block is a line (frozen magnitudes); rem_q: a line's iterations left, 2^k at
  // the load (an arc's end is its pulse counters').
  logic [IncWidth:0]   kpow_q, kpow_d;
  logic [IncWidth-1:0] acc_a_q, acc_a_d, acc_b_q, acc_b_d;
  logic [IncWidth-1:0] mag_a_q, mag_a_d, mag_b_q, mag_b_d;
  logic [IncWidth-1:0] cnt_a_q, cnt_a_d, cnt_b_q, cnt_b_d;
  logic                grow_a_q, grow_a_d, grow_b_q, grow_b_d, a_is_y_q, a_is_y_d;
  logic                line_q, line_d;
  logic [IncWidth:0]   rem_q, rem_d;
  // dir_*_q: step direction per axis, held for the block. step_*_q: the one-clock pulses.
  logic                dir_x_q, dir_x_d, dir_y_q, dir_y_d;
  logic                step_x_q, step_x_d, step_y_q, step_y_d;

  // One axis's half of an iteration: axis A's integrator adds |b|, the other coordinate's
  // magnitude; a carry out of bit k is a step of A, which moves |a| one BLU (up if A's
  // magnitude grows along the arc, else down) and uses one of A's remaining pulses. When b
  // has no pulses left, bit k-1 of the addend is forced on (at least half a step per
  // iteration), so A's last pulses come out even where |b| is 0 (an arc ending on an
  // axis). An axis with no pulses left never steps. In a line both rules are idle: the
  // magnitudes are constants and the integrators independent. It is two functions:
  // integrate() is the adder, settle() the step and what it moves.
  // integrate(): acc + |b| (bit k-1 forced on when b is done), < 2^(k+1).
  function automatic logic [IncWidth:0] integrate(
      input logic                line,        // a line: no finishing rule
      input logic [IncWidth:0]   kpow,        // 2^k (one-hot)
      input logic [IncWidth-1:0] acc,         // A's integrator, < 2^k
      input logic [IncWidth-1:0] other_mag,   // |b|, < 2^k
      input logic                other_done); // b has no pulses left
    logic [IncWidth:0] addend;
    addend = {1'b0, other_mag};
    if (other_done && !line) addend = addend | (kpow >> 1);
    integrate = {1'b0, acc} + addend;
  endfunction

  // settle(): from the sum, {step, acc, mag, cnt} of A after its half-step.
  localparam int HalfWidth = 1 + 3 * IncWidth;
  function automatic logic [HalfWidth-1:0] settle(
      input logic                line,        // a line: the magnitudes do not move
      input logic [IncWidth:0]   kpow,        // 2^k (one-hot)
      input logic [IncWidth:0]   sum,         // integrate()'s
      input logic [IncWidth-1:0] moved,       // |a| + 1 or |a| - 1 (by grow)
      input logic [IncWidth-1:0] mag,         // |a|
      input logic [IncWidth-1:0] cnt);        // A's pulses left
    logic                step;
    logic [IncWidth-1:0] acc_new, mag_new, cnt_new;
    step    = |(sum & kpow) && cnt != '0;
    acc_new = sum[IncWidth-1:0] & ~kpow[IncWidth-1:0];  // clearing bit k subtracts 2^k
    mag_new = step && !line ? moved : mag;
    cnt_new = step ? cnt - 1'b1 : cnt;
    settle = {step, acc_new, mag_new, cnt_new};
  endfunction

  // line: the loaded block is a line (always, without circle mode).
  logic                   line, iterate, active;
  logic [IncWidth:0]      kpow_load;
  // The two half-steps of an iteration: A's first, then B's, which integrates the
  // magnitude A has just moved. B's sum is formed for both outcomes of A's half-step
  // (kept: |a| and A's count as they are; stepped: |a| moved, one pulse fewer) beside A's,
  // and A's step picks one: one carry chain and a multiplexer per clock, not two carry
  // chains in series (the critical path before, docs/bit-widths.md section 6). The moved
  // magnitudes come from registers (grow is one), so they are ready early.
  logic                   first_step, second_step;
  logic [IncWidth-1:0]    first_acc, first_mag, first_cnt, second_acc, second_mag, second_cnt;
  logic [IncWidth-1:0]    moved_a, moved_b;
  logic [IncWidth:0]      first_sum, kept_sum, stepped_sum;

  assign line      = !CircleMode || line_q;
  assign iterate   = strobe_i && !done_o;
  assign active    = load_i || iterate || step_x_q || step_y_q;
  assign kpow_load = (IncWidth + 1)'(1) << k_i;

  always_comb begin
    // The pulses are 0 unless an iteration makes them; every other value is only stored
    // when active (the registers' enable), so it is don't-care ('x) otherwise: the
    // verilated model skips it and synthesis needs no gate for it.
    {step_x_d, step_y_d, carry_x_o, carry_y_o} = '0;
    {kpow_d, acc_a_d, acc_b_d, mag_a_d, mag_b_d, cnt_a_d, cnt_b_d, grow_a_d, grow_b_d,
     a_is_y_d, line_d, rem_d, dir_x_d, dir_y_d, first_step, first_acc, first_mag, first_cnt,
     second_step, second_acc, second_mag, second_cnt, moved_a, moved_b, first_sum, kept_sum,
     stepped_sum} = 'x;
    if (active) begin
      kpow_d   = kpow_q;
      acc_a_d  = acc_a_q;   acc_b_d  = acc_b_q;
      mag_a_d  = mag_a_q;   mag_b_d  = mag_b_q;
      cnt_a_d  = cnt_a_q;   cnt_b_d  = cnt_b_q;
      grow_a_d = grow_a_q;  grow_b_d = grow_b_q;
      a_is_y_d = a_is_y_q;
      line_d   = line_q;    rem_d    = rem_q;
      dir_x_d  = dir_x_q;   dir_y_d  = dir_y_q;
      if (load_i) begin
        // X goes first in the first iteration: A = X, B = Y.
        kpow_d   = kpow_load;
        acc_a_d  = kpow_load[IncWidth:1];
        acc_b_d  = kpow_load[IncWidth:1];
        // A line's magnitude registers hold the other axis's |d| (see the header).
        mag_a_d  = line_i ? cnt_y_i : x_i;
        mag_b_d  = line_i ? cnt_x_i : y_i;
        cnt_a_d  = cnt_x_i;   cnt_b_d  = cnt_y_i;
        grow_a_d = grow_x_i;  grow_b_d = grow_y_i;
        a_is_y_d = 1'b0;
        line_d   = line_i;
        rem_d    = kpow_load;
        dir_x_d  = dir_x_i;   dir_y_d  = dir_y_i;
      end else if (iterate) begin
        moved_a   = mag_a_q + {{(IncWidth - 1){!grow_a_q}}, 1'b1};
        moved_b   = mag_b_q + {{(IncWidth - 1){!grow_b_q}}, 1'b1};
        first_sum = integrate(line, kpow_q, acc_a_q, mag_b_q, cnt_b_q == '0);
        {first_step, first_acc, first_mag, first_cnt} =
            settle(line, kpow_q, first_sum, moved_a, mag_a_q, cnt_a_q);
        kept_sum    = integrate(line, kpow_q, acc_b_q, mag_a_q, cnt_a_q == '0);
        stepped_sum = integrate(line, kpow_q, acc_b_q, line ? mag_a_q : moved_a,
                                cnt_a_q == IncWidth'(1));
        {second_step, second_acc, second_mag, second_cnt} = settle(
            line, kpow_q, first_step ? stepped_sum : kept_sum, moved_b, mag_b_q, cnt_b_q);
        // Swap the roles: B went second, so it goes first in the next iteration.
        acc_a_d  = second_acc;  mag_a_d  = second_mag;  cnt_a_d  = second_cnt;
        acc_b_d  = first_acc;   mag_b_d  = first_mag;   cnt_b_d  = first_cnt;
        grow_a_d = grow_b_q;    grow_b_d = grow_a_q;
        a_is_y_d = !a_is_y_q;
        rem_d    = rem_q - 1'b1;  // counts for a line only (done_o)
        carry_x_o = a_is_y_q ? second_step : first_step;
        carry_y_o = a_is_y_q ? first_step : second_step;
        step_x_d  = carry_x_o;
        step_y_d  = carry_y_o;
      end
    end
  end

  always_ff @(posedge clk_i) begin
    if (!rst_ni) begin
      kpow_q   <= '0;
      acc_a_q  <= '0;  acc_b_q  <= '0;
      mag_a_q  <= '0;  mag_b_q  <= '0;
      cnt_a_q  <= '0;  cnt_b_q  <= '0;
      grow_a_q <= 1'b0;  grow_b_q <= 1'b0;
      a_is_y_q <= 1'b0;
      line_q   <= 1'b0;
      rem_q    <= '0;
      dir_x_q  <= 1'b0;  dir_y_q  <= 1'b0;
      step_x_q <= 1'b0;  step_y_q <= 1'b0;
    end else if (active) begin
      kpow_q   <= kpow_d;
      acc_a_q  <= acc_a_d;   acc_b_q  <= acc_b_d;
      mag_a_q  <= mag_a_d;   mag_b_q  <= mag_b_d;
      cnt_a_q  <= cnt_a_d;   cnt_b_q  <= cnt_b_d;
      grow_a_q <= grow_a_d;  grow_b_q <= grow_b_d;
      a_is_y_q <= a_is_y_d;
      line_q   <= line_d;
      rem_q    <= rem_d;
      dir_x_q  <= dir_x_d;   dir_y_q  <= dir_y_d;
      step_x_q <= step_x_d;  step_y_q <= step_y_d;
    end
  end

  // The registers by axis name, for waves and readers (docs/waves.md); synthesis removes them.
  /* verilator lint_off UNUSEDSIGNAL */
  logic [IncWidth-1:0] acc_x, acc_y, mag_x, mag_y, cnt_x, cnt_y;
  /* verilator lint_on UNUSEDSIGNAL */
  assign acc_x = a_is_y_q ? acc_b_q : acc_a_q;
  assign acc_y = a_is_y_q ? acc_a_q : acc_b_q;
  assign mag_x = a_is_y_q ? mag_b_q : mag_a_q;
  assign mag_y = a_is_y_q ? mag_a_q : mag_b_q;
  assign cnt_x = a_is_y_q ? cnt_b_q : cnt_a_q;
  assign cnt_y = a_is_y_q ? cnt_a_q : cnt_b_q;

  assign step_x_o = step_x_q;
  assign step_y_o = step_y_q;
  assign dir_x_o  = dir_x_q;
  assign dir_y_o  = dir_y_q;
  // An arc ends with its last pulse, a line after its 2^k iterations (its last pulse may come
  // one iteration earlier, and the feed step S = F 2^k is timed for all of them).
  assign done_o   = line ? rem_q == '0 : cnt_a_q == '0 && cnt_b_q == '0;

`ifndef SYNTHESIS
  // The invariant the step detection relies on, checked at every iteration of every
  // verilated run (Verilator --assert) and in every formal proof that reads this module
  // (yosys -formal; synthesis does not): every value is below 2^k, so an integrator's sum
  // is below 2^(k+1) and its carry out of bit k is the only step it can make: at most one
  // step per axis per iteration.
  always_ff @(posedge clk_i) begin
    if (rst_ni && iterate) begin
      a_below_2k: assert ({1'b0, acc_a_q} < kpow_q && {1'b0, acc_b_q} < kpow_q &&
                          {1'b0, mag_a_q} < kpow_q && {1'b0, mag_b_q} < kpow_q &&
                          {1'b0, cnt_a_q} <= kpow_q && {1'b0, cnt_b_q} <= kpow_q);
    end
  end
`endif

endmodule
