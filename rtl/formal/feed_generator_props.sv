// Formal harness of the feed generator (rtl/feed_generator.sv), docs/interpolator.md 5.2.
//
// What is proven, for every block of N iterations with feed F (S = F N), modulus M and the
// DDA's lead LB (2^LB clocks per iteration, feed_generator.sv's LeadBits):
// - ap_timing: the j-th iteration strobe acts at edge L + ceil(j M / S) - 2^LB after the
//   load edge L (one strobe per clock at most, none lost: the phase never needs two), so
//   its iteration ends at L + ceil(j M / S) - 1; and at L + j when saturated
//   (S << LB >= M: then a strobe every clock, which the serial DDA takes when idle);
// - ap_block: so the last one (j = N) ends at L + ceil(M / F) - 1: the block takes ceil(M/F)
//   clocks;
// - ap_run: no strobe unless the block has iterations left; ap_saturated: feed_saturated is
//   S << LB >= M for the whole block.
// Environment (what interp_top guarantees): reset in the first clock, feed_modulus_i static
// (M >= 1), the first load two edges after reset at the earliest (modulus_q is valid), a
// load only when the playing block has no iterations left. The harness plays the DDA: it
// counts the iterations left and gives run_i. ceil() is stated without division:
// t = ceil(x) - 1  <=>  t < x <= t + 1.
// Induction: ai_* tie the phase to the clocks and strobes so far (phase = t S - j M, in
// [0, M)), through formal-tap lines.
module feed_generator_props #(
  parameter int FW = 3,   // F width
  parameter int NW = 3,   // N width
  parameter int MW = 5,   // modulus width
  parameter int LB = 0    // LeadBits
) (
  input logic          clk_i,
  input logic          rst_ni,
  input logic          load_i,
  input logic [FW-1:0] feed_i,     // F of the loading block
  input logic [NW-1:0] count_i,    // N of the loading block
  input logic [MW-1:0] modulus_i
);

  localparam int SW = FW + NW;           // S = F N
  localparam int StepWidth = SW + 1;     // as interp_top: FeedWidth + IncWidth + 1
  localparam int TW = MW + 2;            // clocks of a block: <= M + 1
  localparam int PW = TW + SW + NW + 2;  // products

  logic          strobe, saturated, run;
  logic [SW-1:0] step, f_s_q;  // f_s_q: the model's S of the loaded block (below)
  assign step = SW'(feed_i) * SW'(count_i);

  // run_step_i is the block buffer's out_play_o in interp_top: the loaded block's S.
  feed_generator #(.StepWidth(StepWidth), .ModulusWidth(MW), .LeadBits(LB)) u_dut (
    .clk_i, .rst_ni, .load_i, .step_i(StepWidth'(step)), .step_over_i(1'b0),
    .iterations_i(17'(count_i)), .accel_step_i(MW'(0)), .hold_i(1'b0), .start_i(1'b0), .rapid_i(1'b0),
    .feed_override_i(interp_pkg::OverrideOne), .rapid_override_i(interp_pkg::OverrideOne),
    .run_step_i(StepWidth'(f_s_q)), .run_i(run), .modulus_i,
    .strobe_o(strobe), .saturated_o(saturated)
  );

  // Model: f_age_q edges since reset (saturating at 3); the loaded block (S, F, N); f_left_q
  // iterations left; f_t_q = e - L for the edge e at the end of this clock; f_j_q strobes so
  // far; f_m_q the modulus.
  logic          f_init = 1'b1;
  logic [1:0]    f_age_q;
  logic          f_blk_q;
  logic [FW-1:0] f_f_q;
  logic [NW-1:0] f_n_q, f_left_q, f_j_q;
  logic [TW-1:0] f_t_q;
  logic [MW-1:0] f_m_q;
  logic          f_sat;

  assign run   = f_left_q != '0;
  assign f_sat = (SW + MW + LB)'(f_s_q) << LB >= (SW + MW + LB)'(f_m_q);

  always_ff @(posedge clk_i) begin
    f_init <= 1'b0;
    f_m_q  <= modulus_i;
    if (!rst_ni) begin
      f_age_q <= '0;  f_blk_q <= 1'b0;  f_s_q <= '0;  f_f_q <= '0;  f_n_q <= '0;
      f_left_q <= '0;  f_j_q <= '0;  f_t_q <= '0;
    end else begin
      if (f_age_q != 2'd3) f_age_q <= f_age_q + 1'b1;
      if (load_i) begin
        f_blk_q <= 1'b1;
        f_s_q <= step;  f_f_q <= feed_i;  f_n_q <= count_i;
        f_left_q <= count_i;  f_j_q <= '0;  f_t_q <= TW'(1);
      end else if (run) begin
        f_t_q <= f_t_q + 1'b1;
        if (strobe) begin
          f_left_q <= f_left_q - 1'b1;
          f_j_q <= f_j_q + 1'b1;
        end
      end
    end
  end

  always_comb begin
    if (f_init) assume (!rst_ni);
    if (!f_init) assume (modulus_i == f_m_q && modulus_i != '0);
    if (load_i) assume (f_age_q >= 2'd2 && !run && feed_i != '0 && count_i != '0);
  end

  // The strobe seen in this clock is the j-th (j = f_j_q + 1) and acts at edge L + f_t_q;
  // f_u = f_t_q + 2^LB - 1: its iteration ends at edge L + f_u.
  logic [PW-1:0] f_t, f_u, f_j, f_s, f_m, f_f;
  assign f_t = PW'(f_t_q);
  assign f_u = f_t + PW'((1 << LB) - 1);
  assign f_j = PW'(f_j_q) + 1'b1;
  assign f_s = PW'(f_s_q);
  assign f_m = PW'(f_m_q);
  assign f_f = PW'(f_f_q);

  always_comb begin
    if (!f_init) begin
      if (strobe) ap_run: assert (run);
      if (f_blk_q) ap_saturated: assert (saturated == f_sat);
      if (f_blk_q && strobe) begin
        if (f_sat) begin
          ap_timing_saturated: assert (f_t == f_j);
        end else begin
          ap_timing: assert (f_u * f_s < f_j * f_m && f_j * f_m <= (f_u + 1'b1) * f_s);
        end
        if (f_left_q == NW'(1)) begin
          if (f_sat) ap_block_saturated: assert (f_t == PW'(f_n_q));
          else ap_block: assert (f_u * f_f < f_m && f_m <= (f_u + 1'b1) * f_f);
        end
      end
    end
  end

  // Internal registers for the invariants (driven by scripts/formal.sh).
  // formal-tap: tap_phase = u_dut.phase_q
  // formal-tap: tap_sat = u_dut.saturated_q
  // formal-tap: tap_modulus = u_dut.modulus_q
  // formal-tap: tap_held = u_dut.held_q
  logic [MW:0]        tap_phase;  // PhaseWidth = MW + 1
  logic               tap_sat;
  logic [MW-1:0]      tap_modulus;
  logic               tap_held;     // never: hold_i is tied low here (feed_ramp_props holds)

`ifndef FORMAL_PROPERTIES_ONLY
  logic [PW-1:0]      f_done;
  assign f_done = PW'(f_j_q);

  always_comb begin
    if (!f_init) begin
      if (f_age_q >= 2'd2) ai_modulus: assert (tap_modulus == f_m_q);
      ai_not_held: assert (!tap_held);
      if (!f_blk_q) ai_idle: assert (!run);
      if (f_blk_q) begin
        ai_block: assert (tap_sat == f_sat
                          && f_s_q == SW'(f_f_q) * SW'(f_n_q) && f_f_q != '0
                          && (NW + 1)'(f_left_q) + (NW + 1)'(f_j_q) == (NW + 1)'(f_n_q)
                          && f_m_q != '0 && f_age_q >= 2'd2);
        if (run && f_sat) ai_clocks_saturated: assert (f_t == f_done + 1'b1);
        if (run && !f_sat) begin
          ai_phase: assert (PW'(tap_phase) + f_done * f_m == f_u * f_s);
          ai_phase_below_m: assert (PW'(tap_phase) < f_m);
        end
      end
    end
  end
`endif

  always_comb begin
    if (!f_init) begin
      cp_block_ends: cover (f_blk_q && !f_sat && f_n_q == NW'(3) && f_left_q == '0 && f_t_q > TW'(4));
      cp_saturated_block_ends: cover (f_blk_q && f_sat && f_n_q == NW'(3) && f_left_q == '0);
    end
  end

endmodule
