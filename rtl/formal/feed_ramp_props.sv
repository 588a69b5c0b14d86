// Formal harness of the feed generator's ramp (rtl/feed_generator.sv, Accel = 1,
// docs/motion-control.md section 2).
//
// What is proven, for every block of N iterations and any step S (its over flag too), at a
// modulus M and ramp step du (1 <= du <= cap = (M - 1) >> max(LB, 1)) given as parameters:
// constants keep the slack's arithmetic linear for the solver, and the proofs file runs
// several pairs, du = 1 (the longest ramps) among them.
// - ap_run: no strobe unless the block has iterations left;
// - ap_gap: strobes come at least 2^max(LB, 1) clocks apart, so the serial DDA takes every
//   one (each strobe is one DDA iteration: the pulses are those without the ramp, in order);
// - ap_moving: after its load clock a block with iterations left has u > 0 unless the
//   operator halts it (holds it or overrides it to 0; or did a clock ago): it never stalls;
// - ap_held_still: held at rest, no strobe (no pulse while held); ap_hold_brakes: halted,
//   u falls by du every clock until it is 0 (a hold or a 0 % override brakes at the limit);
// - ap_up_to_target: u rises above du only up to the block's overridden target,
//   min(min(S, cap) P >> OverrideFracBits, cap), P the feed override or, for a rapid
//   traverse, the rapid override (both free, changing at any clock);
// - ap_rest: the block's last strobe comes at u <= du: it ends at rest (one ramp step);
// and, inside the module, a_rate_steps (u moves by 0 or du per clock) and a_rate_capped.
// Environment (what interp_top guarantees): reset in the first clock, feed_modulus_i and
// accel_step_i static, the first load two edges after reset at the earliest, a load only
// when the playing block has no iterations left, iterations_i = its N. The harness plays
// the DDA: it counts the iterations left and gives run_i.
// Induction: ai_* state the slack exactly: K = D M - f, with 2 du (left M - phase - K) =
// u (u + du) (K is the phase to the last strobe less a stop's, B(u) = u (u + du) / (2 du)),
// u a multiple of du, K > -du; the phase since the last strobe for ap_gap; and the override
// multiplier's partial product after i steps, (B (P mod 2^i)) >> i with P's bits above i
// still to add (P not 100 %).
module feed_ramp_props #(
  parameter int NW = 3,   // N width
  parameter int MW = 6,   // modulus width
  parameter int LB = 0,   // LeadBits
  parameter int M  = 37,  // modulus
  parameter int DU = 3    // ramp step
) (
  input logic          clk_i,
  input logic          rst_ni,
  input logic          load_i,
  input logic [MW:0]   step_i,     // S of the loading block (StepWidth = MW + 1)
  input logic          step_over_i,
  input logic [NW-1:0] count_i,    // N of the loading block
  input logic          hold_i,     // the operator, at any clock
  input logic          start_i,
  input logic [interp_pkg::OverrideWidth-1:0] feed_override_i,
  input logic [interp_pkg::OverrideWidth-1:0] rapid_override_i,
  input logic          rapid_i     // the loading block is a rapid traverse
);

  localparam int CapBits = LB > 1 ? LB : 1;
  localparam int Gap = 1 << CapBits;
  localparam int PW = 2 * (MW + NW) + 4;  // products
  localparam int Cap = (M - 1) >> CapBits;
  logic [MW-1:0] modulus_i, accel_i;
  assign modulus_i = MW'(M);
  assign accel_i   = MW'(DU);

  logic          strobe, saturated, run;
  logic [MW:0]   f_step_q;
  logic          f_over_q;

  feed_generator #(.StepWidth(MW + 1), .ModulusWidth(MW), .LeadBits(LB), .Accel(1'b1),
                   .IterWidth(NW)) u_dut (
    .clk_i, .rst_ni, .load_i, .step_i, .step_over_i, .iterations_i(count_i),
    .accel_step_i(accel_i), .hold_i, .start_i, .feed_override_i, .rapid_override_i, .rapid_i,
    .run_step_i(f_step_q), .run_i(run), .modulus_i,
    .strobe_o(strobe), .saturated_o(saturated)
  );

  // Model: f_age_q edges since reset (saturating at 3); the loaded block's S; f_left_q
  // iterations left; f_since_q clocks since the block's last strobe (saturating at Gap);
  // f_first_q: the load clock's edge (u = 0 at it).
  logic          f_init = 1'b1;
  logic [1:0]    f_age_q;
  logic          f_blk_q, f_first_q, f_was_held_q;
  logic [MW-CapBits-1:0] f_rate_q, f_target_q;  // u and the model's target in the previous clock
  logic [NW-1:0] f_left_q;
  logic [CapBits:0] f_since_q;
  localparam logic [MW-1:0] f_m_q = MW'(M), f_du_q = MW'(DU);

  assign run = f_left_q != '0;

  always_ff @(posedge clk_i) begin
    f_init <= 1'b0;
    if (!rst_ni) begin
      f_age_q <= '0;  f_blk_q <= 1'b0;  f_step_q <= '0;  f_over_q <= 1'b0;  f_left_q <= '0;
      f_since_q <= (CapBits + 1)'(Gap);  f_first_q <= 1'b0;  f_was_held_q <= 1'b0;
      f_rate_q <= '0;  f_target_q <= '0;
    end else begin
      if (f_age_q != 2'd3) f_age_q <= f_age_q + 1'b1;
      f_first_q <= load_i;
      f_was_held_q <= halted;
      f_rate_q <= tap_rate;
      f_target_q <= f_target;
      if (load_i) begin
        f_blk_q <= 1'b1;
        f_step_q <= step_i;
        f_over_q <= step_over_i;
        f_left_q <= count_i;
        f_since_q <= (CapBits + 1)'(Gap);
      end else if (run) begin
        if (strobe) begin
          f_left_q <= f_left_q - 1'b1;
          f_since_q <= '0;
        end else if (f_since_q != (CapBits + 1)'(Gap)) begin
          f_since_q <= f_since_q + 1'b1;
        end
      end
    end
  end

  logic [MW-1:0] f_cap;
  assign f_cap = MW'(Cap);
  if (DU < 1 || DU > Cap) $error("feed_ramp_props: DU must be 1 .. (M - 1) >> max(LB, 1)");

  always_comb begin
    if (f_init) assume (!rst_ni);
    if (load_i) assume (f_age_q >= 2'd2 && !run && count_i != '0);
  end

  // Internal registers (driven by scripts/formal.sh).
  // formal-tap: tap_phase = u_dut.phase_q
  // formal-tap: tap_rate = u_dut.rate_q
  // formal-tap: tap_it = u_dut.slack_it_q
  // formal-tap: tap_frac = u_dut.slack_frac_q
  // formal-tap: tap_modulus = u_dut.modulus_q
  // formal-tap: tap_accel = u_dut.accel_q
  // formal-tap: tap_cap = u_dut.cap_q
  // formal-tap: tap_capped = u_dut.capped_q
  // formal-tap: tap_held = u_dut.held_q
  // formal-tap: tap_override = u_dut.override_q
  // formal-tap: tap_mul_left = u_dut.mul_left_q
  // formal-tap: tap_mul_p = u_dut.mul_p_q
  // formal-tap: tap_product = u_dut.product_q
  // formal-tap: tap_base = u_dut.base
  logic [MW:0]        tap_phase;  // PhaseWidth = MW + 1
  logic [MW-CapBits-1:0] tap_rate, tap_cap;
  logic [NW-1:0]      tap_it;
  logic [MW-1:0]      tap_frac, tap_modulus, tap_accel;
  logic               tap_capped, tap_held;
  localparam int OW = interp_pkg::OverrideWidth;
  localparam int OvrShift = OW - interp_pkg::OverrideFracBits;
  logic [OW-1:0] tap_override, tap_mul_p;
  logic [$clog2(OW+1)-1:0] tap_mul_left;
  logic [MW-CapBits+OvrShift-1:0] tap_product;
  logic [MW-CapBits-1:0] tap_base;

  // The model's target: S capped, times P, capped; halted (held or P = 0) it is 0.
  localparam int TW = MW + interp_pkg::OverrideWidth + 1;
  logic          halted;
  logic [TW-1:0] f_scaled;
  logic [MW-CapBits-1:0] f_target;
  assign halted   = tap_held || tap_override == '0;
  assign f_scaled = ((f_over_q || (TW'(f_step_q) > TW'(Cap)) ? TW'(Cap) : TW'(f_step_q))
                     * TW'(tap_override)) >> interp_pkg::OverrideFracBits;
  assign f_target = halted ? '0 : f_scaled > TW'(Cap) ? (MW - CapBits)'(Cap)
                                                      : (MW - CapBits)'(f_scaled);

  logic [PW-1:0] f_u, f_du, f_m, f_k_pos, f_left, f_v;
  assign f_u     = PW'(tap_rate);
  assign f_v     = f_u / PW'(DU);
  assign f_du    = PW'(f_du_q);
  assign f_m     = PW'(f_m_q);
  assign f_k_pos = PW'(tap_it) * f_m;                    // K = f_k_pos - f
  assign f_left  = PW'(f_left_q) * f_m - PW'(tap_phase);  // phase to the last strobe

  always_comb begin
    if (!f_init && f_blk_q) begin
      if (strobe) ap_run: assert (run);
      if (strobe) ap_gap: assert (f_since_q >= (CapBits + 1)'(Gap - 1));
      if (run && !f_first_q && !halted && !f_was_held_q) ap_moving: assert (tap_rate != '0);
      if (tap_held && tap_rate == '0) ap_held_still: assert (!strobe);
      if (tap_rate > f_rate_q && f_rate_q != '0) ap_up_to_target: assert (tap_rate <= f_target_q);
      if (f_was_held_q && run && !f_first_q && f_rate_q != '0)
        ap_hold_brakes: assert (PW'(tap_rate) + f_du == PW'(f_rate_q));
      if (strobe && f_left_q == NW'(1)) ap_rest: assert (f_u <= f_du);
    end
  end

`ifndef FORMAL_PROPERTIES_ONLY
  always_comb begin
    if (!f_init) begin
      if (f_age_q >= 2'd2) begin
        ai_static: assert (tap_modulus == f_m_q && tap_accel == f_du_q && PW'(tap_cap) == PW'(f_cap));
      end
      if (!f_blk_q) ai_idle: assert (!run && tap_rate == '0);
      if (f_blk_q && run) begin
        ai_phase: assert (PW'(tap_phase) < f_m && PW'(tap_frac) < f_m && f_age_q >= 2'd2);
        ai_capped: assert (tap_capped == (f_over_q || (PW'(f_step_q) << CapBits) >= f_m));
        // u = v du, v a level; K + B(u) = left with B(u) = du v (v + 1) / 2; and K > -du.
        ai_rate: assert (f_u == f_v * f_du && f_u <= PW'(f_cap) && (!f_first_q || tap_rate == '0));
        ai_slack: assert (PW'(2) * (f_left + PW'(tap_frac) - f_k_pos) == f_v * (f_u + f_du)
                          && f_k_pos + f_du > PW'(tap_frac));
        // Since the last strobe the phase grew by at most u <= cap per clock from below u.
        if (f_since_q < (CapBits + 1)'(Gap))
          ai_gap: assert (PW'(tap_phase) < (PW'(f_since_q) + 1'b1) * PW'(f_cap));
      end
      // The multiplier after i = OW - left steps; its base changes only at a load, which
      // restarts it (at 100 % it is not used, and not restarted).
      if (tap_override != interp_pkg::OverrideOne)
        ai_mul: assert (PW'(tap_mul_left) <= PW'(OW) &&
                      PW'(tap_mul_p) == (PW'(tap_override) >> (PW'(OW) - PW'(tap_mul_left))) &&
                      PW'(tap_product) ==
                        ((PW'(tap_base) << OvrShift) *
                         (PW'(tap_override) & ((PW'(1) << (PW'(OW) - PW'(tap_mul_left))) - 1'b1)))
                        >> (PW'(OW) - PW'(tap_mul_left)));
    end
  end
`endif

  always_comb begin
    if (!f_init) begin
      // A ramped block of 3 iterations that reached 2 du ends (at rest).
      cp_ramped_block_ends: cover (f_blk_q && f_left_q == NW'(1) && strobe && f_du_q < f_cap);
      // Held to rest mid-block, then started again.
      cp_held_and_started: cover (f_was_held_q && !tap_held && run && tap_rate == '0 && f_left_q > NW'(1));
      // Cruising at an override below 100 % and above 0, slower than the block's S.
      cp_overridden: cover (f_blk_q && run && tap_override < interp_pkg::OverrideOne &&
                            !halted && tap_rate == f_target && TW'(f_target) < TW'(f_step_q));
    end
  end

endmodule
