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
// Golden twin: the section "Feed generator" of GoldenInterp::tick()
// (sc_model/golden/interp_top.h).
module feed_generator #(
  parameter int StepWidth    = 49,
  parameter int ModulusWidth = 48,
  parameter int LeadBits     = 0
) (
  input  logic                    clk_i,
  input  logic                    rst_ni,
  input  logic                    load_i,     // a block loads at this edge
  input  logic [StepWidth-1:0]    step_i,     // its S = F * N, modulo 2^StepWidth
  input  logic                    step_over_i, // S >= 2^StepWidth: saturated whatever M
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
  localparam int CmpWidth   = StepWidth + LeadBits > ModulusWidth ? StepWidth + LeadBits
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

  // Load and run never coincide: a block loads when the player is idle or finishing.
  always_comb begin
    modulus     = PhaseWidth'(modulus_q);
    sum         = 'x;  // used only while running unsaturated
    {borrow, over, reached} = 'x;
    strobe_o    = 1'b0;
    phase_d     = phase_q;
    saturated_d = saturated_q;
    if (load_i) begin
      phase_d     = PhaseWidth'(lead_step);
      saturated_d = step_over_i || at_least(lead_step, CmpWidth'(modulus_q));
    end else if (run_i) begin
      if (saturated_q) begin
        strobe_o = 1'b1;
      end else begin
        // One subtraction gives both the compare (no borrow: sum >= M) and sum - M.
        // Unsaturated, S < 2^RunStepWidth: its low bits are all of it.
        sum            = phase_q + PhaseWidth'(RunStepWidth'(run_step_i));
        {borrow, over} = {1'b0, sum} - {1'b0, modulus};
        reached        = !borrow;
        strobe_o = reached;
        phase_d  = reached ? over : sum;
      end
    end
  end

  always_ff @(posedge clk_i) begin
    modulus_q <= modulus_i;
    if (!rst_ni) begin
      phase_q     <= '0;
      saturated_q <= 1'b0;
    end else begin
      phase_q     <= phase_d;
      saturated_q <= saturated_d;
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
    end
  end
`endif

endmodule
