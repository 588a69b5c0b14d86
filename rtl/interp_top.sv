// Interpolator top: plays a punched tape of line and quadrant arc blocks into step/dir
// pulses.
//
// What: tape_decoder (with arc_prepare) -> block_buffer ("next" block) -> player
// (feed_generator + dda_circle, which plays G01 lines and G02/G03 arcs) -> position
// counters, plus the machine status. Ports and parameters are the contract
// of docs/architecture.md; the microarchitecture and the clock-by-clock timing are in
// docs/interpolator.md, which the golden model (sc_model/golden/) follows too. The golden
// twin is GoldenInterp (sc_model/golden/interp_top.h); its tick() holds the twins of
// block_buffer.sv, feed_generator.sv and position_counter.sv as named sections, and this
// module's status logic; CircleDda (sc_model/golden/dda_circle.h) is dda_circle.sv's.
// Timing: every output is a register or a function of registers (Moore). A block loads at
// an edge where the buffer holds one and the player is idle or in the finishing clock of
// the previous block, so blocks follow without gap clocks when the reader keeps up. An
// error found while decoding is raised only when no good block is left to play.
module interp_top #(
  // Increment register width W: |dx|, |dy|, |i|, |j| of a block <= 2^IncWidth - 1 BLU.
  parameter int IncWidth       = 16,
  // Fraction digits of X, Y, I, J on tape: BLU = 10^-FracDigits mm.
  parameter int FracDigits     = 3,
  // F register (units of 10^-FeedFracDigits 1/min) and its fraction digits on tape.
  parameter int FeedWidth      = 32,
  parameter int FeedFracDigits = 3,
  // Signed position counters, BLU.
  parameter int PosWidth       = 32,
  // N (block sequence number).
  parameter int SeqWidth       = 20,
  // Frame offset counter (error reports).
  parameter int OffsetWidth    = 32,
  // Width of feed_modulus_i.
  parameter int ModulusWidth   = 48,
  // The microarchitecture ("arch"; the golden model's InterpConfig::arch, every command's
  // --arch): 1 = serial, what the boards ship and the default; 0 = parallel. Serial
  // (docs/interpolator.md 3.2, 3.5, 4 and 5.6): the DDA, of the player and of an arc's dry
  // run, is dda_serial.sv, 2P clocks per iteration (P = W rounded up to a power of two)
  // instead of one, each digit's x10 + d a pass of NumWidth clocks on a one-bit adder
  // (tape_word_parser.sv), and the block buffer in block RAM, whose registered read makes a
  // block loadable one clock later (block_buffer.sv). Fewer logic cells (docs/bit-widths.md);
  // the player's top rate is one iteration per 2P clocks, and 3.5 says when the slower dry
  // run leaves gaps.
  parameter bit BitSerial   = 1'b1,
  // Circle mode (G02/G03 quadrant arcs; the golden model's InterpConfig::circle_mode): 1
  // built in; 0 the machine of paper 000, lines only, whose first stage writes only chords:
  // an arc block is refused with error 13 (ErrNoCircleMode), and the arc's checks, dry run
  // and the DDA's arc logic are not built (the iCEstick's configuration, docs/board.md).
  parameter bit CircleMode  = 1'b1,
  // The feed ramp (feed_generator.sv): accel_step_i > 0 ramps every block's rate from rest
  // and back, at most accel_step_i per clock; 0, or Accel = 0, plays every block at its S.
  parameter bit Accel       = 1'b1,
  // The miscellaneous functions M00, M01 (the pause until start_i), M03 and M05 (tool_o):
  // 1 built in; 0 refuses them (error 6, unsupported code) and builds none of their logic,
  // tool_o and paused_o being 0 (the iCEstick's configuration: its HX1K is full).
  parameter bit MiscFunctions = 1'b1
) (
  input  logic                    clk_i,
  input  logic                    rst_ni,
  // Static configuration: 60 * f_clk * 10^FeedFracDigits, and the feed step S of a rapid
  // traverse (G00): the rapid rate in BLU/min, times 10^FeedFracDigits; the ramp step du
  // (InterpConfig::accel_step_for(): an acceleration limit; 0: no ramps).
  input  logic [ModulusWidth-1:0] feed_modulus_i,
  input  logic [ModulusWidth-1:0] rapid_step_i,
  input  logic [ModulusWidth-1:0] accel_step_i,
  // The operator: feed hold and cycle start (feed_generator.sv).
  input  logic                    hold_i,
  input  logic                    start_i,
  // The operator's feed override (G01, G02, G03) and rapid override (G00), with the ramp:
  // the fraction of a block's rate it plays at, 2^OverrideFracBits = 100 % (feed_generator.sv).
  input  logic [interp_pkg::OverrideWidth-1:0] feed_override_i,
  input  logic [interp_pkg::OverrideWidth-1:0] rapid_override_i,
  // The machine's stops: E-stop and the X and Y limit switches (high: tripped). The first
  // seen at an edge while the program runs stops the machine for good (until reset): the
  // error state with its own code from that edge, and from the next edge on no block
  // loads, no iteration starts and a serial iteration in flight emits nothing, so the
  // last step pulse is one of that edge and the position counters count exactly the
  // pulses that went out (the status logic below).
  input  logic                    estop_i,
  input  logic                    limit_x_i,
  input  logic                    limit_y_i,
  // The optional stop switch: on, an M01 block pauses the program as M00 does.
  input  logic                    optional_stop_i,
  // Tape reader.
  input  logic [7:0]              frame_i,
  input  logic                    frame_valid_i,
  input  logic                    tape_end_i,
  output logic                    frame_ready_o,
  // Axes.
  output logic                    step_x_o,
  output logic                    dir_x_o,
  output logic                    step_y_o,
  output logic                    dir_y_o,
  output logic [PosWidth-1:0]     pos_x_o,
  output logic [PosWidth-1:0]     pos_y_o,
  // Status.
  output logic [SeqWidth-1:0]     block_n_o,
  output logic                    busy_o,
  output logic                    done_o,
  output logic                    error_o,
  output logic [interp_pkg::ErrCodeWidth-1:0] error_code_o,
  output logic [SeqWidth-1:0]     error_block_o,
  output logic [OffsetWidth-1:0]  error_offset_o,
  output logic                    feed_saturated_o,
  // The tool (spindle, laser, torch, pen): on from the load of an M03 block, off after the
  // motion of an M05 block, and off for good at the end of the program, a tape error or a
  // stop. The program paused after an M00 block (or M01 with optional_stop_i) and waits for
  // start_i.
  output logic                    tool_o,
  output logic                    paused_o
);

  localparam int KWidth = $clog2(IncWidth + 1);
  localparam int IterWidth = Accel ? IncWidth + 1 : 1;  // the block's N (block_record.def)
  // The DDA's clocks per iteration are 2^LeadBits: 1 (dda_circle), or 2P with BitSerial
  // (dda_serial.sv; P = 2^$clog2(IncWidth)).
  localparam int LeadBits = BitSerial ? $clog2(IncWidth) + 1 : 0;
  // The feed step S = F * N of a block (N <= 2^(W+1) iterations), as wide as its job: any S
  // with S << LeadBits >= M saturates the block whatever its value (feed_generator.sv), so
  // the decoder keeps S modulo 2^StepWidth, StepWidth = ModulusWidth - LeadBits + 1 (or
  // exact), and a flag for S >= 2^StepWidth.
  localparam int ExactStepWidth = FeedWidth + IncWidth + 1;
  localparam int StepWidth = ExactStepWidth < ModulusWidth - LeadBits + 1 ? ExactStepWidth
                                                                          : ModulusWidth - LeadBits + 1;
  // block_t, the decoded block (sw/host/tape/block_record.def, the macro in
  // 0_interp_pkg.sv): the decoder fills it, the buffer stores it, the player reads it.
  `INTERP_BLOCK_T
  // The buffer's width, from the struct: Yosys 0.23 takes $bits of a signal only, Icarus 11
  // (bench/sim) evaluates $bits of a struct signal in a parameter wrongly (2): each gets the
  // form it reads right.
  block_t dec_block, next_block;
`ifdef __ICARUS__
  localparam int BlockWidth = $bits(block_t);
`else
  localparam int BlockWidth = $bits(dec_block);
`endif

  // Decoder -> buffer.
  logic                   dec_valid, buf_ready;
  logic                   dec_end, dec_tape_ended, dec_err;
  logic [interp_pkg::ErrCodeWidth-1:0] dec_err_code;
  logic [SeqWidth-1:0]    dec_err_block;
  logic [OffsetWidth-1:0] dec_err_offset;

  // Buffer -> player: the next block (next_valid), and S of the playing one.
  logic                   next_valid, next_arc;
  logic [StepWidth-1:0]   play_step;

  // Player: the feed generator's strobes iterate the DDA; its carries count the positions.
  // finished: the playing block's iterations are over (the DDA's done). words: the serial
  // DDA still reads the playing block's words from the buffer.
  logic              load, strobe, finished, saturated, words;
  logic              carry_x, carry_y;

  // busy_q: a block is loaded and not finished. block_n_q: its N (the last one when idle).
  // done_q / error_q: the machine has stopped at the end of the program / on a tape error
  // or a stop. stop_q: which stop input stopped it (0: none, 1: E-stop, 2: X limit,
  // 3: Y limit).
  logic                busy_q, busy_d, done_q, done_d, error_q, error_d;
  logic [SeqWidth-1:0] block_n_q, block_n_d;
  logic [1:0]          stop_q, stop_d;
  logic                stopped;
  assign stopped = stop_q != '0;
  // The playing block's M word that acts after its motion (latched at its load: the buffer
  // then holds the next block): M05, M00, M01. tool_q: the tool output. paused_q: the
  // program waits for cycle start; pause: the playing block ends at this edge with a pause.
  logic                tool_q, tool_d, paused_q, paused_d, pause;
  logic                after_tool_off_q, after_stop_q, after_optional_stop_q;

  tape_decoder #(
    .IncWidth(IncWidth), .FracDigits(FracDigits), .FeedWidth(FeedWidth),
    .FeedFracDigits(FeedFracDigits), .SeqWidth(SeqWidth), .OffsetWidth(OffsetWidth),
    .StepWidth(StepWidth), .ModulusWidth(ModulusWidth), .BitSerial(BitSerial),
    .CircleMode(CircleMode), .Accel(Accel), .MiscFunctions(MiscFunctions)
  ) u_decoder (
    .clk_i, .rst_ni, .rapid_step_i,
    .frame_i, .frame_valid_i, .tape_end_i, .frame_ready_o,
    .blk_valid_o(dec_valid), .blk_ready_i(buf_ready), .blk_o(dec_block),
    .end_o(dec_end), .tape_ended_o(dec_tape_ended), .err_o(dec_err), .err_code_o(dec_err_code),
    .err_block_o(dec_err_block), .err_offset_o(dec_err_offset)
  );

  // With BitSerial the buffer is a block RAM, but N (the first field: the top bits) stays in
  // flip-flops, so a board that leaves block_n_o unused loses its logic (block_buffer.sv).
  block_buffer #(.Width(BlockWidth), .InRam(BitSerial), .FlopBits(SeqWidth),
                 .PlayBits(StepWidth)) u_buffer (
    .clk_i, .rst_ni,
    .in_valid_i(dec_valid), .in_ready_o(buf_ready),
    .in_block_i(dec_block),
    .pop_i(load), .hold_i(words),
    .out_valid_o(next_valid), .out_block_o(next_block), .out_play_o(play_step)
  );

  assign next_arc = interp_pkg::motion_is_arc(next_block.motion);

  // A block loads when one waits and the player is idle or finishing the previous block
  // (unless that one pauses the program), while the program neither is paused nor has been
  // stopped by a stop input.
  assign pause = MiscFunctions && busy_q && finished &&
                 (after_stop_q || (after_optional_stop_q && optional_stop_i));
  assign load  = next_valid && (!busy_q || (finished && !pause)) && !stopped && !paused_q;

  feed_generator #(.StepWidth(StepWidth), .ModulusWidth(ModulusWidth), .LeadBits(LeadBits),
                   .Accel(Accel), .IterWidth(IncWidth + 1))
  u_feed (
    .clk_i, .rst_ni,
    .load_i(load), .step_i(next_block.step), .step_over_i(next_block.step_over),
    .iterations_i((IncWidth + 1)'(next_block.iterations)), .accel_step_i, .hold_i, .start_i,
    .feed_override_i, .rapid_override_i,
    .rapid_i(next_block.motion == interp_pkg::MotionRapid),
    .run_step_i(play_step),
    .run_i(busy_q && !finished && !stopped), .modulus_i(feed_modulus_i),
    .strobe_o(strobe), .saturated_o(saturated)
  );

  // A line's magnitudes are its increments; an arc's start about its centre is (-I, -J):
  // its magnitudes are |I|, |J|. The player's DDA is dda_circle, or with BitSerial
  // dda_serial: u_circle stays outside a generate block so that the default's VCD scopes
  // keep their names (docs/waves.md); with BitSerial it never loads and synthesis removes
  // it.
  logic circle_carry_x, circle_carry_y, circle_step_x, circle_dir_x, circle_step_y;
  logic circle_dir_y, circle_done;
  dda_circle #(.IncWidth(IncWidth), .KWidth(KWidth), .CircleMode(CircleMode)) u_circle (
    .clk_i, .rst_ni,
    .load_i(load && !BitSerial), .line_i(!next_arc), .k_i(next_block.k), .x_i(next_block.i),
    .y_i(next_block.j), .cnt_x_i(next_block.dx), .cnt_y_i(next_block.dy),
    .grow_x_i(next_block.grow_x), .grow_y_i(next_block.grow_y),
    .dir_x_i(!next_block.dx_neg), .dir_y_i(!next_block.dy_neg),
    .strobe_i(strobe && !BitSerial),
    .carry_x_o(circle_carry_x), .carry_y_o(circle_carry_y),
    .step_x_o(circle_step_x), .dir_x_o(circle_dir_x), .step_y_o(circle_step_y),
    .dir_y_o(circle_dir_y), .done_o(circle_done)
  );
  if (BitSerial) begin : g_serial
    logic iterate;  // the feed generator's strobes are the iterations
    /* verilator lint_off UNUSEDSIGNAL */
    logic [6:0] unused_circle;
    /* verilator lint_on UNUSEDSIGNAL */
    assign unused_circle = {circle_carry_x, circle_carry_y, circle_step_x, circle_dir_x,
                            circle_step_y, circle_dir_y, circle_done};
    // The DDA reads the buffered words one bit per clock in its first pass (bit_q).
    logic [$clog2(IncWidth)-1:0] bit_q;
    function automatic logic word_bit(input logic [IncWidth-1:0] word,
                                      input logic [$clog2(IncWidth)-1:0] i);
      word_bit = 32'(i) < IncWidth ? word[i] : 1'b0;
    endfunction
    dda_serial #(.IncWidth(IncWidth), .KWidth(KWidth), .CircleMode(CircleMode)) u_serial (
      .clk_i, .rst_ni,
      .load_i(load), .line_i(!next_arc), .k_i(next_block.k),
      .x_bit_i(word_bit(next_block.i, bit_q)), .y_bit_i(word_bit(next_block.j, bit_q)),
      .cnt_x_bit_i(word_bit(next_block.dx, bit_q)), .cnt_y_bit_i(word_bit(next_block.dy, bit_q)),
      .bit_o(bit_q), .grow_x_i(next_block.grow_x), .grow_y_i(next_block.grow_y),
      .dir_x_i(!next_block.dx_neg), .dir_y_i(!next_block.dy_neg),
      .strobe_i(strobe), .mute_i(stopped), .iterate_o(iterate),
      .carry_x_o(carry_x), .carry_y_o(carry_y),
      .step_x_o, .dir_x_o, .step_y_o, .dir_y_o,
      .words_o(words), .done_o(finished)
    );
`ifndef SYNTHESIS
    // Checked at every edge of every verilated run (Verilator --assert) and in the formal
    // proofs of the machine (yosys -formal; synthesis does not): every strobe of a block
    // that is not saturated starts an iteration. The feed generator's lead keeps its strobes
    // 2P clocks apart, the length of an iteration, so none comes while one runs and none is
    // lost (a saturated block strobes every clock and iterates as fast as the DDA can).
    always_ff @(posedge clk_i) begin
      if (rst_ni) begin
        a_strobe_iterates: assert (!strobe || iterate ||
                                   (saturated && !(Accel && accel_step_i != '0)));
      end
    end
`endif
  end else begin : g_parallel
    assign {carry_x, carry_y, step_x_o, dir_x_o, step_y_o, dir_y_o, finished} =
        {circle_carry_x, circle_carry_y, circle_step_x, circle_dir_x, circle_step_y,
         circle_dir_y, circle_done};
    assign words = 1'b0;
  end

  position_counter #(.PosWidth(PosWidth)) u_pos_x (
    .clk_i, .rst_ni, .count_i(carry_x), .up_i(dir_x_o), .pos_o(pos_x_o)
  );

  position_counter #(.PosWidth(PosWidth)) u_pos_y (
    .clk_i, .rst_ni, .count_i(carry_y), .up_i(dir_y_o), .pos_o(pos_y_o)
  );

  // Status. The decoder's error and end wait until nothing is left to play.
  always_comb begin
    busy_d    = busy_q;
    block_n_d = block_n_q;
    if (load) begin
      busy_d    = 1'b1;
      block_n_d = next_block.n;
    end else if (busy_q && finished) begin
      busy_d = 1'b0;  // finished with no next block: a gap (or the end)
    end
    // buf_ready: the buffer is empty (with BitSerial, a block just taken is held but not
    // yet readable: next_valid is still low). A paused program ends, or reports its tape
    // error, after cycle start.
    error_d = error_q | (dec_err & !busy_q & buf_ready & !paused_q);
    done_d  = done_q | (dec_end & dec_tape_ended & !busy_q & buf_ready & !paused_q);
    // A stop input, while the program runs (not after its end or a tape error): E-stop
    // first, then X, then Y.
    stop_d = stop_q;
    if (!stopped && !done_q && !error_q) begin
      if (estop_i) stop_d = 2'd1;
      else if (limit_x_i) stop_d = 2'd2;
      else if (limit_y_i) stop_d = 2'd3;
    end
    // A stop wins over an end of program raised at the same edge, and none comes after it.
    error_d = error_d | (stop_d != '0);
    done_d  = done_d & (stop_d == '0);
    // A pause from the edge its block ends at, until a cycle start after it or a stop.
    paused_d = MiscFunctions && (pause || (paused_q && !start_i)) && !error_d;
    // The tool: off after an M05 block's motion, on at an M03 block's load (an M03 loading
    // as an M05 block ends wins), off when the program stops for any reason.
    tool_d = tool_q;
    if (busy_q && finished && after_tool_off_q) tool_d = 1'b0;
    if (load && next_block.tool_on) tool_d = 1'b1;
    if (error_d || done_d || !MiscFunctions) tool_d = 1'b0;
  end

  always_ff @(posedge clk_i) begin
    if (!rst_ni) begin
      busy_q    <= 1'b0;
      block_n_q <= '0;
      done_q    <= 1'b0;
      error_q   <= 1'b0;
      stop_q    <= '0;
      tool_q    <= 1'b0;
      paused_q  <= 1'b0;
      {after_tool_off_q, after_stop_q, after_optional_stop_q} <= '0;
    end else begin
      busy_q    <= busy_d;
      block_n_q <= block_n_d;
      done_q    <= done_d;
      error_q   <= error_d;
      stop_q    <= stop_d;
      tool_q    <= tool_d;
      paused_q  <= paused_d;
      if (load) begin
        {after_tool_off_q, after_stop_q, after_optional_stop_q} <=
            {next_block.tool_off, next_block.stop, next_block.optional_stop};
      end
    end
  end

  assign block_n_o        = block_n_q;
  assign busy_o           = busy_q;
  assign done_o           = done_q;
  assign error_o          = error_q;
  // A stop's report: its code, the block playing (or the last played), no tape offset.
  logic [interp_pkg::ErrCodeWidth-1:0] stop_code;
  always_comb begin
    case (stop_q)
      2'd1:    stop_code = interp_pkg::ErrEmergencyStop;
      2'd2:    stop_code = interp_pkg::ErrLimitX;
      default: stop_code = interp_pkg::ErrLimitY;
    endcase
  end
  assign error_code_o     = !error_q ? '0 : stopped ? stop_code : dec_err_code;
  assign error_block_o    = !error_q ? '0 : stopped ? block_n_q : dec_err_block;
  assign error_offset_o   = error_q && !stopped ? dec_err_offset : '0;
  assign feed_saturated_o = busy_q & saturated;
  assign tool_o           = tool_q;
  assign paused_o         = paused_q;

`ifndef SYNTHESIS
  // Checked at every edge of every verilated run and in the machine's formal proofs: a
  // paused program has no block in the player (no pulse can come until cycle start), and
  // the tool is off once the program has stopped or ended.
  always_ff @(posedge clk_i) begin
    if (rst_ni) begin
      a_paused_idle: assert (!paused_q || !busy_q);
      a_tool_off_when_over: assert (!tool_q || !(error_q || done_q));
    end
  end
`endif

endmodule
