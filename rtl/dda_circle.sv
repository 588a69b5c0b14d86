// Circle DDA of one quadrant arc: two cross-coupled integrators with immediate update.
//
// What (docs/circle-dda.md): coordinates are magnitudes relative to the arc's centre. The X
// integrator adds |y| and the Y integrator adds |x| at every iteration (modulus 2^k, k =
// bit length of the largest magnitude on the arc); a carry is a step of that axis and
// moves its magnitude by one BLU. The second half-step of an iteration already sees the
// magnitude the first one moved (semi-implicit: the orbit closes, it does not spiral out
// like forward Euler), and the order alternates every iteration, X first on the first one,
// which cancels the first-order tilt of the closed curve. Per-axis pulse counters (|dx|,
// |dy|) stop each axis exactly at the programmed end; the block's iterations are over
// when both are 0 (done_o). The golden twin is sc_model/golden/circle_dda.h.
// Timing: load_i loads the block at an edge where no iteration happens; an iteration
// happens at an edge with strobe_i while !done_o and its pulses show after that edge.
module dda_circle #(
  parameter int IncWidth = 16,
  parameter int KWidth   = $clog2(IncWidth + 1)
) (
  input  logic                clk_i,
  input  logic                rst_ni,
  // The loading block's geometry (arc_geometry.sv).
  input  logic                load_i,
  input  logic [KWidth-1:0]   k_i,
  input  logic [IncWidth-1:0] x_i,        // |x| of the start, relative to the centre
  input  logic [IncWidth-1:0] y_i,        // |y| of the start
  input  logic [IncWidth-1:0] cnt_x_i,    // |dx|: X pulses of the block
  input  logic [IncWidth-1:0] cnt_y_i,    // |dy|
  input  logic                grow_x_i,   // |x| grows along the arc
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
  logic [IncWidth:0]   kpow_q, kpow_d;
  // acc_*_q: the integrators, in [0, 2^k), half at the load (rounding to nearest).
  // mag_*_q: |x|, |y| relative to the centre. cnt_*_q: pulses left per axis.
  logic [IncWidth-1:0] acc_x_q, acc_x_d, acc_y_q, acc_y_d;
  logic [IncWidth-1:0] mag_x_q, mag_x_d, mag_y_q, mag_y_d;
  logic [IncWidth-1:0] cnt_x_q, cnt_x_d, cnt_y_q, cnt_y_d;
  // grow_*_q: the magnitude grows at that axis's steps (fixed for the block).
  // dir_*_q: step direction, held for the block. step_*_q: the one-clock step pulses.
  logic                grow_x_q, grow_x_d, grow_y_q, grow_y_d;
  logic                dir_x_q, dir_x_d, dir_y_q, dir_y_d;
  logic                step_x_q, step_x_d, step_y_q, step_y_d;
  // y_first_q: this iteration steps Y before X; toggles every iteration (X first after load).
  logic                y_first_q, y_first_d;

  logic                iterate;
  logic [IncWidth:0]   kpow_load;

  // The two half-steps of an iteration: "a" is the axis going first, "b" the second.
  logic                a_step, b_step;
  logic [IncWidth-1:0] a_acc, a_other_mag, a_mag, a_cnt, a_acc_new, a_mag_new, a_cnt_new;
  logic [IncWidth-1:0] b_acc, b_mag, b_cnt, b_acc_new, b_mag_new, b_cnt_new;
  logic                a_grow, a_other_done, b_grow;

  assign iterate   = strobe_i && !done_o;
  assign kpow_load = (IncWidth + 1)'(1) << k_i;

  // Operands of the first half-step: registers only (no combinational loop).
  always_comb begin
    if (y_first_q) begin
      a_acc = acc_y_q;  a_mag = mag_y_q;  a_cnt = cnt_y_q;  a_grow = grow_y_q;
      a_other_mag = mag_x_q;  a_other_done = cnt_x_q == '0;
      b_acc = acc_x_q;  b_mag = mag_x_q;  b_cnt = cnt_x_q;  b_grow = grow_x_q;
    end else begin
      a_acc = acc_x_q;  a_mag = mag_x_q;  a_cnt = cnt_x_q;  a_grow = grow_x_q;
      a_other_mag = mag_y_q;  a_other_done = cnt_y_q == '0;
      b_acc = acc_y_q;  b_mag = mag_y_q;  b_cnt = cnt_y_q;  b_grow = grow_y_q;
    end
  end

  circle_half_step #(.Width(IncWidth)) u_first (
    .kpow_i(kpow_q), .acc_i(a_acc), .other_mag_i(a_other_mag), .other_done_i(a_other_done),
    .mag_i(a_mag), .grow_i(a_grow), .cnt_i(a_cnt),
    .step_o(a_step), .acc_o(a_acc_new), .mag_o(a_mag_new), .cnt_o(a_cnt_new)
  );

  // The second half-step integrates the magnitude the first one has just moved.
  circle_half_step #(.Width(IncWidth)) u_second (
    .kpow_i(kpow_q), .acc_i(b_acc), .other_mag_i(a_mag_new), .other_done_i(a_cnt_new == '0),
    .mag_i(b_mag), .grow_i(b_grow), .cnt_i(b_cnt),
    .step_o(b_step), .acc_o(b_acc_new), .mag_o(b_mag_new), .cnt_o(b_cnt_new)
  );

  assign carry_x_o = iterate && (y_first_q ? b_step : a_step);
  assign carry_y_o = iterate && (y_first_q ? a_step : b_step);

  always_comb begin
    kpow_d    = kpow_q;
    acc_x_d   = acc_x_q;   acc_y_d  = acc_y_q;
    mag_x_d   = mag_x_q;   mag_y_d  = mag_y_q;
    cnt_x_d   = cnt_x_q;   cnt_y_d  = cnt_y_q;
    grow_x_d  = grow_x_q;  grow_y_d = grow_y_q;
    dir_x_d   = dir_x_q;   dir_y_d  = dir_y_q;
    y_first_d = y_first_q;
    step_x_d  = 1'b0;
    step_y_d  = 1'b0;
    if (load_i) begin
      kpow_d    = kpow_load;
      acc_x_d   = kpow_load[IncWidth:1];
      acc_y_d   = kpow_load[IncWidth:1];
      mag_x_d   = x_i;       mag_y_d  = y_i;
      cnt_x_d   = cnt_x_i;   cnt_y_d  = cnt_y_i;
      grow_x_d  = grow_x_i;  grow_y_d = grow_y_i;
      dir_x_d   = dir_x_i;   dir_y_d  = dir_y_i;
      y_first_d = 1'b0;
    end else if (iterate) begin
      if (y_first_q) begin
        acc_y_d = a_acc_new;  mag_y_d = a_mag_new;  cnt_y_d = a_cnt_new;
        acc_x_d = b_acc_new;  mag_x_d = b_mag_new;  cnt_x_d = b_cnt_new;
      end else begin
        acc_x_d = a_acc_new;  mag_x_d = a_mag_new;  cnt_x_d = a_cnt_new;
        acc_y_d = b_acc_new;  mag_y_d = b_mag_new;  cnt_y_d = b_cnt_new;
      end
      y_first_d = !y_first_q;
      step_x_d  = carry_x_o;
      step_y_d  = carry_y_o;
    end
  end

  always_ff @(posedge clk_i) begin
    if (!rst_ni) begin
      kpow_q    <= '0;
      acc_x_q   <= '0;  acc_y_q  <= '0;
      mag_x_q   <= '0;  mag_y_q  <= '0;
      cnt_x_q   <= '0;  cnt_y_q  <= '0;
      grow_x_q  <= 1'b0;  grow_y_q <= 1'b0;
      dir_x_q   <= 1'b0;  dir_y_q  <= 1'b0;
      step_x_q  <= 1'b0;  step_y_q <= 1'b0;
      y_first_q <= 1'b0;
    end else begin
      kpow_q    <= kpow_d;
      acc_x_q   <= acc_x_d;   acc_y_q  <= acc_y_d;
      mag_x_q   <= mag_x_d;   mag_y_q  <= mag_y_d;
      cnt_x_q   <= cnt_x_d;   cnt_y_q  <= cnt_y_d;
      grow_x_q  <= grow_x_d;  grow_y_q <= grow_y_d;
      dir_x_q   <= dir_x_d;   dir_y_q  <= dir_y_d;
      step_x_q  <= step_x_d;  step_y_q <= step_y_d;
      y_first_q <= y_first_d;
    end
  end

  assign step_x_o = step_x_q;
  assign step_y_o = step_y_q;
  assign dir_x_o  = dir_x_q;
  assign dir_y_o  = dir_y_q;
  assign done_o   = cnt_x_q == '0 && cnt_y_q == '0;

endmodule
