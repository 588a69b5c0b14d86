// Step pulse stretcher for one axis: the interpolator's one-clock step pulses made long
// enough for a stepper driver, with the direction set up before and held after each step.
//
// What: a pulse taken (step_i) starts, if its direction differs from dir_o, a SETUP phase
// of setup_cycles_i clocks after dir_o changes; then step_o is high for pulse_cycles_i
// clocks (HIGH), then low for at least low_cycles_i clocks (LOW) before the next pulse may
// start. dir_o changes only between pulses, so it is held pulse_cycles_i + low_cycles_i
// clocks after each rising edge of step_o. A pulse that arrives while one is being sent
// waits in a one-deep buffer (with its direction); a pulse arriving while that buffer is
// full is lost and raises overrun_o for one clock (the board reports it as an error): the
// steps came faster than the driver may take them.
// Timing: a pulse taken in IDLE with an unchanged direction raises step_o at the next
// edge. All outputs are registers. The cycle counts are static (constants at the board top
// computed from ns parameters; ports so the lock-step test can vary them), each >= 1.
// Golden twin: sc_model/board/step_stretcher_model.h (StepStretcherModel), compared every
// clock by tests/sc_model/board/test_board_lockstep.cpp.
module step_stretcher #(
  parameter int CountWidth = 16
) (
  input  logic                  clk_i,
  input  logic                  rst_ni,
  input  logic [CountWidth-1:0] setup_cycles_i,
  input  logic [CountWidth-1:0] pulse_cycles_i,
  input  logic [CountWidth-1:0] low_cycles_i,
  input  logic                  step_i,
  input  logic                  dir_i,
  output logic                  step_o,
  output logic                  dir_o,
  output logic                  overrun_o
);

  typedef enum logic [1:0] {StIdle, StSetup, StHigh, StLow} state_e;

  // count_q: the clocks of the phase so far, this one included (1 at its first clock); the
  // phase ends at its last clock, where count_q equals its length. An up count compared
  // with the phase's length (a constant on the board: a few gates) needs no multiplexer
  // of lengths into the counter.
  state_e                state_q, state_d;
  logic [CountWidth-1:0] count_q, count_d, phase_cycles;
  // pend_q / pend_dir_q: the buffered pulse and its direction.
  logic                  pend_q, pend_d, pend_dir_q, pend_dir_d;
  logic                  step_q, step_d, dir_q, dir_d, overrun_q, overrun_d;
  // take: a pulse starts this clock; take_dir: its direction; took_pend: from the buffer.
  // phase_end: the phase's last clock.
  logic                  take, take_dir, took_pend, phase_end;

  always_comb begin
    unique case (state_q)
      StSetup: phase_cycles = setup_cycles_i;
      StHigh:  phase_cycles = pulse_cycles_i;
      default: phase_cycles = low_cycles_i;
    endcase
  end
  assign phase_end = count_q == phase_cycles;

  always_comb begin
    state_d    = state_q;
    count_d    = count_q + 1'b1;
    step_d     = step_q;
    dir_d      = dir_q;
    take       = 1'b0;
    took_pend  = 1'b0;
    take_dir   = dir_i;
    unique case (state_q)
      StIdle: begin
        if (pend_q) begin
          take      = 1'b1;
          took_pend = 1'b1;
          take_dir  = pend_dir_q;
        end else if (step_i) begin
          take = 1'b1;
        end
        if (take) begin
          if (take_dir != dir_q) begin
            dir_d   = take_dir;
            state_d = StSetup;
          end else begin
            step_d  = 1'b1;
            state_d = StHigh;
          end
        end
      end
      StSetup: if (phase_end) begin
                 step_d  = 1'b1;
                 state_d = StHigh;
               end
      StHigh: if (phase_end) begin
                step_d  = 1'b0;
                state_d = StLow;
              end
      StLow: if (phase_end) state_d = StIdle;
      default: state_d = StIdle;
    endcase
    // A new phase starts at its first clock.
    if (state_d != state_q) count_d = CountWidth'(1);
    // The buffer: an incoming pulse that is not taken directly waits; one more is lost.
    pend_d     = pend_q && !took_pend;
    pend_dir_d = pend_dir_q;
    overrun_d  = 1'b0;
    if (step_i && !(take && !took_pend)) begin
      if (pend_d) overrun_d = 1'b1;
      else begin
        pend_d     = 1'b1;
        pend_dir_d = dir_i;
      end
    end
  end

  always_ff @(posedge clk_i) begin
    if (!rst_ni) begin
      state_q    <= StIdle;
      count_q    <= '0;
      pend_q     <= 1'b0;
      pend_dir_q <= 1'b0;
      step_q     <= 1'b0;
      dir_q      <= 1'b0;
      overrun_q  <= 1'b0;
    end else begin
      state_q    <= state_d;
      count_q    <= count_d;
      pend_q     <= pend_d;
      pend_dir_q <= pend_dir_d;
      step_q     <= step_d;
      dir_q      <= dir_d;
      overrun_q  <= overrun_d;
    end
  end

  assign step_o    = step_q;
  assign dir_o     = dir_q;
  assign overrun_o = overrun_q;

endmodule
