// Two-axis line DDA (method L1): two integrators sharing one iteration counter.
//
// What: a block of k = bit length of max(|dx|, |dy|) runs exactly 2^k iterations; each
// iteration (a strobe from the feed generator) adds the increments to the integrators,
// whose carries are the step pulses (dda_integrator.sv).
// Timing: load_i loads the block at an edge where no iteration happens; an iteration
// happens at an edge with strobe_i while rem_q != 0 and its pulses show after that edge.
// rem_zero_o marks the block's finishing clock (all iterations done), after which
// interp_top loads the next block or goes idle.
// Golden twin: the section "Line DDA" of GoldenInterp::tick()
// (sc_model/golden/interp_top.h).
module dda_line #(
  parameter int IncWidth = 16,
  parameter int KWidth   = $clog2(IncWidth + 1)
) (
  input  logic                clk_i,
  input  logic                rst_ni,
  input  logic                load_i,
  input  logic [KWidth-1:0]   k_i,        // k of the loading block
  input  logic [IncWidth-1:0] dx_i,
  input  logic                dx_neg_i,
  input  logic [IncWidth-1:0] dy_i,
  input  logic                dy_neg_i,
  input  logic                strobe_i,   // one iteration at this edge (only while running)
  output logic                carry_x_o,  // pulses emitted at this edge (for the counters)
  output logic                carry_y_o,
  output logic                step_x_o,
  output logic                dir_x_o,
  output logic                step_y_o,
  output logic                dir_y_o,
  output logic                rem_zero_o
);

  // kpow_q: 2^k of the playing block, one-hot (the integrators' carry bit).
  // rem_q: iterations left, 2^k at the load.
  logic [IncWidth:0] kpow_q, kpow_d, rem_q, rem_d;
  logic [IncWidth:0] kpow_load;
  logic              iterate;

  assign iterate = strobe_i && rem_q != '0;

  always_comb begin
    kpow_load = '0;
    kpow_d    = kpow_q;
    rem_d     = rem_q;
    if (load_i) begin
      kpow_load = (IncWidth + 1)'(1) << k_i;
      kpow_d = kpow_load;
      rem_d  = kpow_load;
    end else if (iterate) begin
      rem_d = rem_q - 1'b1;
    end
  end

  always_ff @(posedge clk_i) begin
    if (!rst_ni) begin
      kpow_q <= '0;
      rem_q  <= '0;
    end else begin
      kpow_q <= kpow_d;
      rem_q  <= rem_d;
    end
  end

  dda_integrator #(.Width(IncWidth)) u_axis_x (
    .clk_i, .rst_ni, .load_i,
    .start_i(kpow_load[IncWidth:1]), .inc_i(dx_i), .neg_i(dx_neg_i),
    .iterate_i(iterate), .kpow_i(kpow_q),
    .carry_o(carry_x_o), .step_o(step_x_o), .dir_o(dir_x_o)
  );

  dda_integrator #(.Width(IncWidth)) u_axis_y (
    .clk_i, .rst_ni, .load_i,
    .start_i(kpow_load[IncWidth:1]), .inc_i(dy_i), .neg_i(dy_neg_i),
    .iterate_i(iterate), .kpow_i(kpow_q),
    .carry_o(carry_y_o), .step_o(step_y_o), .dir_o(dir_y_o)
  );

  assign rem_zero_o = rem_q == '0;

endmodule
