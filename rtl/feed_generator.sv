// Feed generator: inverse-time feed (G93) as a phase accumulator of DDA iteration strobes.
//
// What: a block of N DDA iterations (2^k for a line, the circle DDA's count for an arc)
// must take 1/F minutes. Every clock the phase grows by the block's step S = F * N (the
// decoder computes it) and is compared with the modulus M = 60 * f_clk * 10^FeedFracDigits;
// reaching M issues one iteration strobe and subtracts M. So N iterations take M/F clocks,
// rounded up (docs/interpolator.md 5.2). If S >= M the block wants more than one iteration
// per clock: it is saturated and runs one iteration every clock instead.
// S comes twice: step_i at the load edge (for the phase's start and the saturation), and
// run_step_i from the edge after it, while the block plays (the block buffer's out_play_o:
// in block RAM on the board, so S needs no flip-flops here).
// Timing: at the load edge phase_q = S << LeadBits (the load clock counts as the first
// add) and saturated_q is set; from then on, while run_i, strobe_o is
// combinational from the registers and acts in the same edge as the DDA iteration it
// starts. LeadBits is 0 for dda_circle.sv, whose iteration is that edge. dda_serial.sv
// (BitSerial) takes 2^LeadBits clocks per iteration and a block loads only when its
// predecessor's last iteration has ended, 2^LeadBits - 1 clocks after the one-clock DDA
// would load it: the phase starts 2^LeadBits adds ahead, so iteration j of a block still
// ends ceil(j M / S) - 1 clocks after its load and every block lasts ceil(M / F) clocks.
// Strobes then come at least 2^LeadBits clocks apart, each when the DDA is idle, as long
// as S << LeadBits < M; a block with S << LeadBits >= M is saturated (docs/interpolator.md
// 5.2).
// Ramp (Accel, with accel_step_i = du > 0; docs/motion-control.md): the phase grows by a
// rate u instead of S. u starts at 0 at the load and moves by du per clock toward the
// target min(S, cap), cap = (M - 1) >> max(LeadBits, 1) (at most one strobe in 2 clocks,
// or per serial iteration: no saturation). It brakes on the slack K: the phase units to the
// block's last strobe less those a stop from u takes, B(u) = u + (u - du) + ... + du,
// kept as whole iterations D and a fraction f, K = D M - f (no multiplier: D starts at N,
// f at 0). Each clock: up if u + du <= target and K > 2u + du (from rest, if K > 0); else
// stay if u <= target and K > u, or creep if u = du and K > 0; else down. A feed hold
// (hold_i until start_i) makes the target 0 and turns off the start from rest and the
// creep. Every strobe still starts the same DDA iteration, so the pulses are those
// without ramps; only time stretches. With du = 0 (or Accel = 0) it is the generator
// above, clock for clock.
// Overrides (with the ramp only): the target is min(min(S, cap) P >> OverrideFracBits, cap),
// P the feed override, or for a rapid traverse (rapid_i at its load) the rapid override,
// registered. So an override scales the rate the block would play at, and u follows a
// change of it at du per clock like any other; P = 0 stops the block as a hold does. The
// product comes from a shift-and-add multiplier, one bit of P per clock (one adder, not a
// multiplier array of some thousand LUT4s at the default widths): it restarts at each load
// and each change of P, unless P is 100 %, where the target is min(S, cap) itself; while
// it runs (OverrideWidth clocks) the target is u, so u holds (from rest, creeps at du)
// until the new target is there. So a machine at 100 % ramps as without overrides, and a
// top that ties the overrides to 100 % has no multiplier.
// Golden twin: the section "Feed generator" of GoldenInterp::tick() and
// GoldenInterp::ramp_edge() (sc_model/golden/interp_top.h).
module feed_generator #(
  parameter int StepWidth    = 49,
  parameter int ModulusWidth = 48,
  parameter int LeadBits     = 0,
  parameter bit Accel        = 1'b0,  // the ramp's logic is built
  parameter int IterWidth    = 17     // N, a block's iterations, < 2^IterWidth
) (
  input  logic                    clk_i,
  input  logic                    rst_ni,
  input  logic                    load_i,     // a block loads at this edge
  input  logic [StepWidth-1:0]    step_i,     // its S = F * N, modulo 2^StepWidth
  input  logic                    step_over_i, // S >= 2^StepWidth: saturated whatever M
  input  logic [IterWidth-1:0]    iterations_i, // its N (read with Accel only)
  input  logic [ModulusWidth-1:0] accel_step_i, // du, static; 0: no ramp
  // Feed hold: from the clock after hold_i until the clock after start_i (cycle start). Held,
  // a plain block strobes no more at once; a ramped one brakes at du per clock to rest.
  input  logic                    hold_i,
  input  logic                    start_i,
  // The overrides (read with the ramp only): P for feed blocks, and for rapid traverses,
  // in units of 2^-OverrideFracBits; rapid_i: the block loading at this edge is a G00.
  input  logic [interp_pkg::OverrideWidth-1:0] feed_override_i,
  input  logic [interp_pkg::OverrideWidth-1:0] rapid_override_i,
  input  logic                    rapid_i,
  // S of the playing block (after its load edge); only its low ModulusWidth - LeadBits
  // bits are read: a block with any higher bit set is saturated.
  /* verilator lint_off UNUSEDSIGNAL */
  input  logic [StepWidth-1:0]    run_step_i,
  /* verilator lint_on UNUSEDSIGNAL */
  input  logic                    run_i,      // the playing block has iterations left
  input  logic [ModulusWidth-1:0] modulus_i,  // feed_modulus_i (static)
  output logic                    strobe_o,   // one DDA iteration at this edge
  output logic                    saturated_o
);

  // Only a block that is not saturated uses the phase, and then S << LeadBits < M: S needs
  // ModulusWidth - LeadBits bits, the phase (< M) and phase + S (< 2M) ModulusWidth (+ 1),
  // whatever StepWidth is.
  localparam int PhaseWidth = ModulusWidth + 1;
  localparam int RunStepWidth = ModulusWidth - LeadBits;
  // The ramp's cap is (M - 1) >> CapBits (below).
  localparam int CapBits    = LeadBits > 1 ? LeadBits : 1;
  // The compares of S << LeadBits and S << CapBits with M.
  localparam int CmpWidth   = StepWidth + CapBits > ModulusWidth ? StepWidth + CapBits
                                                                 : ModulusWidth;

  // modulus_q: feed_modulus_i registered (static configuration; registered so that no
  // logic depends on an input combinationally). Valid from the first clock on, long before
  // the first block can load (the fourth clock after reset), so it has no reset: a board
  // that ties feed_modulus_i to a constant (rtl/fpga/interp_ice40_top.sv) then has a
  // register with a constant input and no reset value, which synthesis replaces by the
  // constant, and the compares with M fold.
  logic [ModulusWidth-1:0] modulus_q;
  // phase_q: accumulated feed, always < M when not saturated. saturated_q: S << LeadBits
  // >= M, one iteration per clock.
  logic [PhaseWidth-1:0] phase_q, phase_d;
  logic                  saturated_q, saturated_d;

  logic [PhaseWidth-1:0] sum, modulus, over;
  logic                  reached, borrow;
  logic [CmpWidth-1:0]   lead_step;  // S << LeadBits

  assign lead_step = CmpWidth'(step_i) << LeadBits;

  // The ramp (Accel). u <= cap = (M - 1) >> CapBits < 2^RateWidth. accel_q: du registered
  // like M (static, no reset). capped_q: the block's S > cap (S << CapBits >= M, or S's
  // over flag), so its target is cap. slack_it_q, slack_frac_q: the slack K as D M - f.
  localparam int RateWidth  = ModulusWidth - CapBits;
  logic [ModulusWidth-1:0] accel_q;
  logic [RateWidth-1:0]    cap_q, rate_q, rate_d, du, target;
  logic                    capped_q, capped_d, ramp_on, held_q, halt;
  // rapid_q: the block plays at the rapid override. override_q: its P, registered.
  // The multiplier: product_q = (B (P mod 2^i)) >> i after i of its steps, B = base <<
  // (OvrWidth - OverrideFracBits), base = min(S, cap): after all OvrWidth steps it is
  // base P >> OverrideFracBits, exact (each step's shift drops only bits below the result).
  // mul_p_q: the bits of P still to add; mul_left_q: the steps left (0: the product).
  localparam int OvrWidth  = interp_pkg::OverrideWidth;
  localparam int OvrShift  = OvrWidth - interp_pkg::OverrideFracBits;
  localparam int ProdWidth = RateWidth + OvrShift;  // the product < 2B, B < 2^ProdWidth
  logic                    rapid_q;
  logic [OvrWidth-1:0]     override_q, override_d, mul_p_q, mul_p_d;
  logic [$clog2(OvrWidth+1)-1:0] mul_left_q, mul_left_d;
  logic [RateWidth-1:0]    base;
  logic [ProdWidth-1:0]    product_q, product_d;
  /* verilator lint_off UNUSEDSIGNAL */
  logic [ProdWidth:0]      mul_sum;  // its bit 0 is shifted out
  /* verilator lint_on UNUSEDSIGNAL */
  logic [IterWidth-1:0]    slack_it_q, slack_it_d;
  logic [ModulusWidth-1:0] slack_frac_q, slack_frac_d;
  logic [RateWidth:0]      up_rate;                       // u + du
  logic [ModulusWidth:0]   stay_sum;                      // f + u
  logic [ModulusWidth+1:0] up_sum;                        // f + 2u + du
  // f + u - M, f + 2u + du - M and - 2M: read only when they do not borrow, then < M.
  /* verilator lint_off UNUSEDSIGNAL */
  logic [ModulusWidth:0]   stay_over;
  logic [ModulusWidth+1:0] up_over, up_over2;
  /* verilator lint_on UNUSEDSIGNAL */
  logic                    stay_borrow, up_borrow, up_borrow2, stay_wrap;
  logic [1:0]              up_wraps;
  logic [ModulusWidth-1:0] stay_frac, up_frac;

  assign du      = RateWidth'(accel_q);
  assign ramp_on = Accel && accel_q != '0;

  // a >= b, decided by the highest bit where they differ. Written out because synthesis
  // builds `>=` as a subtraction on a carry chain, one logic cell a bit even when b is a
  // constant (the board's M); as logic it folds to a few LUT4s there (74 logic cells fewer
  // on the board, docs/bit-widths.md section 6), and it is smaller in interp_top too.
  function automatic logic at_least(input logic [CmpWidth-1:0] a, input logic [CmpWidth-1:0] b);
    at_least = 1'b1;
    for (int i = 0; i < CmpWidth; i++) begin
      if (a[i] != b[i]) at_least = a[i];
    end
  endfunction

  // The ramp's sums (used only while a ramped block runs): f + u and its wrap past M;
  // f + 2u + du (f + u, plus u + du) and its wraps past M and 2M (f < M, 2u + du < 3M/2).
  // K > u exactly when D exceeds the wraps of f + u (K - u = (D - wraps) M - the rest, the
  // rest < M), and K > 2u + du when D exceeds those of f + 2u + du.
  always_comb begin
    // Held or overridden to 0, the target is 0 and u does not start from rest or creep.
    halt       = held_q || override_q == '0;
    base       = capped_q ? cap_q : RateWidth'(run_step_i);
    target     = halt ? '0 : override_q == interp_pkg::OverrideOne ? base
               : mul_left_q != '0 ? rate_q
               : product_q > ProdWidth'(cap_q) ? cap_q : RateWidth'(product_q);
    // The multiplier's next step: restart at a load (the new block's base from the next
    // clock on) or when P changes, to anything but 100 %; else add B if P's next bit is
    // set, and halve.
    override_d = !Accel ? '0 : (load_i ? rapid_i : rapid_q) ? rapid_override_i : feed_override_i;
    mul_sum    = {1'b0, product_q} + (mul_p_q[0] ? (ProdWidth + 1)'(base) << OvrShift : '0);
    if (Accel && override_d != interp_pkg::OverrideOne && (load_i || override_d != override_q)) begin
      product_d  = '0;
      mul_p_d    = override_d;
      mul_left_d = ($bits(mul_left_q))'(OvrWidth);
    end else if (mul_left_q != '0) begin
      product_d  = mul_sum[ProdWidth:1];
      mul_p_d    = mul_p_q >> 1;
      mul_left_d = mul_left_q - 1'b1;
    end else begin
      product_d  = product_q;
      mul_p_d    = mul_p_q;
      mul_left_d = mul_left_q;
    end
    up_rate  = {1'b0, rate_q} + {1'b0, du};
    stay_sum = (ModulusWidth + 1)'(slack_frac_q) + (ModulusWidth + 1)'(rate_q);
    {stay_borrow, stay_over} = {1'b0, stay_sum} - {2'b0, modulus_q};
    stay_wrap = !stay_borrow;
    stay_frac = stay_wrap ? stay_over[ModulusWidth-1:0] : stay_sum[ModulusWidth-1:0];
    up_sum   = (ModulusWidth + 2)'(stay_sum) + (ModulusWidth + 2)'(up_rate);
    {up_borrow, up_over}   = {1'b0, up_sum} - {3'b0, modulus_q};
    {up_borrow2, up_over2} = {1'b0, up_sum} - {2'b0, modulus_q, 1'b0};
    up_wraps = !up_borrow2 ? 2'd2 : !up_borrow ? 2'd1 : 2'd0;
    up_frac  = !up_borrow2 ? up_over2[ModulusWidth-1:0]
             : !up_borrow ? up_over[ModulusWidth-1:0] : up_sum[ModulusWidth-1:0];
  end

  // Load and run never coincide: a block loads when the player is idle or finishing.
  always_comb begin
    modulus     = PhaseWidth'(modulus_q);
    sum         = 'x;  // used only while running unsaturated (or ramped)
    {borrow, over, reached} = 'x;
    strobe_o    = 1'b0;
    phase_d     = phase_q;
    saturated_d = saturated_q;
    rate_d       = rate_q;
    capped_d     = capped_q;
    slack_it_d   = slack_it_q;
    slack_frac_d = slack_frac_q;
    if (load_i) begin
      phase_d     = ramp_on ? '0 : PhaseWidth'(lead_step);
      saturated_d = step_over_i || at_least(lead_step, CmpWidth'(modulus_q));
      // A ramped block starts at rest, its slack N M.
      rate_d       = '0;
      capped_d     = step_over_i || at_least(CmpWidth'(step_i) << CapBits,
                                             CmpWidth'(modulus_q));
      slack_it_d   = iterations_i;
      slack_frac_d = '0;
    end else if (run_i) begin
      if (saturated_q && !ramp_on) begin
        strobe_o = !held_q;
      end else if (ramp_on || !held_q) begin
        // One subtraction gives both the compare (no borrow: sum >= M) and sum - M.
        // Unsaturated, S < 2^RunStepWidth: its low bits are all of it; ramped, the rate u.
        sum            = phase_q + (ramp_on ? PhaseWidth'(rate_q)
                                            : PhaseWidth'(RunStepWidth'(run_step_i)));
        {borrow, over} = {1'b0, sum} - {1'b0, modulus};
        reached        = !borrow;
        strobe_o = reached;
        phase_d  = reached ? over : sum;
      end
      // The ramp's move for the next clock: up, stay (or creep at du), or down.
      if (ramp_on) begin
        // From rest (not held) whenever K > 0; otherwise while a stop from u + du fits.
        if (rate_q == '0 && !halt ? slack_it_q != '0
                                    : up_rate <= {1'b0, target} &&
                                      slack_it_q > IterWidth'(up_wraps)) begin
          rate_d       = up_rate[RateWidth-1:0];
          slack_it_d   = slack_it_q - IterWidth'(up_wraps);
          slack_frac_d = up_frac;
        end else if ((rate_q <= target && slack_it_q > IterWidth'(stay_wrap)) ||
                     (rate_q == du && !halt && slack_it_q != '0)) begin
          slack_it_d   = slack_it_q - IterWidth'(stay_wrap);
          slack_frac_d = stay_frac;
        end else if (rate_q != '0) begin
          rate_d = rate_q - du;  // B(u - du) = B(u) - u: K stays
        end
      end
    end
  end

  always_ff @(posedge clk_i) begin
    modulus_q <= modulus_i;
    accel_q   <= Accel ? accel_step_i : '0;
    cap_q     <= RateWidth'((modulus_i - 1'b1) >> CapBits);
    if (!rst_ni) begin
      held_q       <= 1'b0;
      rapid_q      <= 1'b0;
      override_q   <= Accel ? interp_pkg::OverrideOne : '0;
      product_q    <= '0;
      mul_p_q      <= '0;
      mul_left_q   <= '0;
      phase_q      <= '0;
      saturated_q  <= 1'b0;
      rate_q       <= '0;
      capped_q     <= 1'b0;
      slack_it_q   <= '0;
      slack_frac_q <= '0;
    end else begin
      held_q       <= hold_i || (held_q && !start_i);
      rapid_q      <= load_i ? rapid_i : rapid_q;
      override_q   <= override_d;
      product_q    <= product_d;
      mul_p_q      <= mul_p_d;
      mul_left_q   <= mul_left_d;
      phase_q      <= phase_d;
      saturated_q  <= saturated_d;
      rate_q       <= rate_d;
      capped_q     <= capped_d;
      slack_it_q   <= slack_it_d;
      slack_frac_q <= slack_frac_d;
    end
  end

  assign saturated_o = saturated_q;

`ifndef SYNTHESIS
  // The invariant the shared next-state logic relies on (its 'x defaults are used only
  // while running), checked at every edge of every verilated run (Verilator --assert) and
  // in every formal proof that reads this module (yosys -formal; synthesis does not): a
  // block loads only when the player is idle or finishing, so load and run never meet.
  always_ff @(posedge clk_i) begin
    if (rst_ni) begin
      a_load_not_running: assert (!(load_i && run_i));
      // The ramp: u never passes its cap (so a serial block strobes at most once per
      // iteration) and moves by at most du per clock.
      a_rate_capped: assert (rate_q <= cap_q || !ramp_on);
      a_rate_steps: assert (load_i || !ramp_on || rate_d == rate_q || rate_d == rate_q + du ||
                            rate_d == rate_q - du);
    end
  end
`endif

endmodule
