// Board core: the interpolator fed by a serial tape reader, with stepper-driver outputs,
// LEDs and status lines; everything of a board except its pins and its clock/reset.
//
// What: uart_rx -> byte_fifo -> interp_top (rtl/interp_top.sv) -> step_stretcher per axis,
// and status_line on the TX line; operator_pins brings the operator's buttons and switches
// to interp_top. Each received byte is one tape frame (bit 7 = ISO 840
// parity). The EOT frame (interp_pkg::LinkEndOfTape) ends the tape: it drives interp_top's
// tape_end_i, so the program is done after M02/M30, and a tape cut short before that is an
// error, as on a real reader. Flow control (docs/board.md): cts_no (to the host UART's
// CTS#, active low) goes high while the FIFO holds CtsStopLevel bytes or more, and XOFF /
// XON go out on TX when the level crosses XoffLevel / XonLevel. With RealtimeBytes,
// host_link takes the host's realtime commands out of the received bytes (they drive
// operator_pins as its buttons do) and the status line acknowledges every LinkAckBytes
// bytes taken out of the FIFO, so the host can count characters instead.
// Board errors join the interpolator's (error LED and an "E" status line): the FIFO
// overflowed (flow control failed), a UART framing error, a step pulse was lost (steps
// faster than the driver timing allows), a realtime byte came alone; codes
// interp_pkg::BoardErr* (the link's list, sw/host/tape/board_link.def). Their block is the
// current block_n and their offset the number of bytes the FIFO took before the error.
// The interpolator is built as the board's configuration asks (arch, circle mode), with
// 20-bit positions, N and frame offsets; the status line sends their low bits (N's low
// 4 * StatusBlockDigits, the others' low 4 * StatusDigits), which the host resolves
// (sc_model/board/status_text.h), so synthesis keeps only those bits. The obs_<output>_o ports show interp_top's own
// outputs (one per line of sc_model/golden/interp_outputs.def, which board-sim reads them
// by), the FIFO level and the received bytes to the board simulation; a real board leaves
// them unconnected, and synthesis removes what only they read. Static configuration comes
// in on ports (the board tops tie them to constants): bit_cycles_i clocks per UART bit,
// feed_modulus_i, rapid_step_i, accel_step_i (the feed ramp's step; 0: no ramp), and the
// stretchers' clock counts.
// Timing: every output is a register or a function of registers.
// Golden twins: GoldenInterp for interp_top (board-sim compares nothing itself: it replays
// the outputs into the play monitors), the UART, stretcher, operator pins and host link
// models of sc_model/board/.
module board_core #(
  parameter int FifoAddrWidth = $clog2(interp_pkg::LinkFifoBytes),
  parameter int CtsStopLevel  = 240,
  parameter int XoffLevel     = 128,
  parameter int XonLevel      = 32,
  // UART bit clock counter (bit_cycles_i >= 4) and step timing counters: narrow enough
  // to leave room for the interpolator on the part (12 MHz: >= 2930 baud, <= 21 us).
  parameter int DivWidth      = 12,
  parameter int StretchWidth  = 8,
  // The arithmetic bit-serial (interp_top's BitSerial): fewer logic cells; the DDA of the
  // player and of the arc's dry run takes 2P clocks per iteration (375 000 iterations per
  // second at 12 MHz and W = 16), above what the step stretchers let through on most
  // blocks (docs/interpolator.md 3.5 and 5.6), and a digit's pass (NumWidth clocks) is
  // hidden between the UART's frames.
  parameter bit BitSerial  = 1'b1,
  // Circle mode (interp_top's CircleMode): the iCEstick's core is built without it.
  parameter bit CircleMode = 1'b1,
  // M00, M01, M03 and M05 (interp_top's MiscFunctions): the iCEstick's core has no room.
  parameter bit MiscFunctions = 1'b1,
  // The feed ramp (interp_top's Accel): the iCEstick's core has no room for it either.
  parameter bit Accel = 1'b1,
  // The operator's pins (operator_pins.sv): feed hold, cycle start and override buttons,
  // E-stop, limit and optional stop switches. Without them (the iCEstick) nothing stops
  // the machine but reset, the overrides are 100 %, and cycle start is held pressed: a
  // pause ends at once.
  parameter bit OperatorPins = 1'b1,
  // Realtime bytes on the link and character counting (host_link.sv): the host's commands
  // act as the operator's buttons, so only with them.
  parameter bit RealtimeBytes = OperatorPins,
  // The buttons' debounce sample period, 2^DebounceWidth clocks (5.5 ms at 12 MHz).
  parameter int DebounceWidth = interp_pkg::OperatorDebounceWidth,
  // The interpolator's widths on the board (+-524 mm of travel at 1 um, N and the frame
  // offset below 2^20), as the golden model's board configuration has them
  // (sc_model/board/boards.cpp); the status line sends their low bits.
  parameter int PosWidth    = 20,
  parameter int SeqWidth    = 20,
  parameter int OffsetWidth = 20,
  // feed_modulus_i's width: enough for the board's clock (board_top).
  parameter int ModulusWidth = 48
) (
  input  logic        clk_i,
  input  logic        rst_ni,
  input  logic [DivWidth-1:0] bit_cycles_i,
  input  logic [ModulusWidth-1:0] feed_modulus_i,
  input  logic [ModulusWidth-1:0] rapid_step_i,
  input  logic [ModulusWidth-1:0] accel_step_i,
  input  logic [StretchWidth-1:0] setup_cycles_i,
  input  logic [StretchWidth-1:0] pulse_cycles_i,
  input  logic [StretchWidth-1:0] low_cycles_i,
  // The operator's pins, active high (pressed, tripped, on), asynchronous.
  input  logic        hold_i,
  input  logic        start_i,
  input  logic        feed_up_i,
  input  logic        feed_down_i,
  input  logic        feed_reset_i,
  input  logic        rapid_cycle_i,
  input  logic        estop_i,
  input  logic        limit_x_i,
  input  logic        limit_y_i,
  input  logic        optional_stop_i,
  // UART to the host.
  input  logic        rx_i,
  output logic        tx_o,
  output logic        cts_no,
  // Stepper drivers.
  output logic        step_x_o,
  output logic        dir_x_o,
  output logic        step_y_o,
  output logic        dir_y_o,
  // The tool (M03 on, M05 off): a spindle relay, a laser's or torch's enable, a pen.
  output logic        tool_o,
  // LEDs (active high).
  output logic        led_busy_o,
  output logic        led_done_o,
  output logic        led_error_o,
  // The interpolator's outputs, for the board simulation (interp_outputs.def's names).
  output logic        obs_frame_ready_o,
  output logic        obs_step_x_o,
  output logic        obs_dir_x_o,
  output logic        obs_step_y_o,
  output logic        obs_dir_y_o,
  output logic [PosWidth-1:0]    obs_pos_x_o,
  output logic [PosWidth-1:0]    obs_pos_y_o,
  output logic [SeqWidth-1:0]    obs_block_n_o,
  output logic        obs_busy_o,
  output logic        obs_done_o,
  output logic        obs_error_o,
  output logic [interp_pkg::ErrCodeWidth-1:0] obs_error_code_o,
  output logic [SeqWidth-1:0]    obs_error_block_o,
  output logic [OffsetWidth-1:0] obs_error_offset_o,
  output logic        obs_feed_saturated_o,
  output logic        obs_tool_o,
  output logic        obs_paused_o,
  output logic [FifoAddrWidth:0] obs_fifo_level_o,
  output logic [7:0]  obs_rx_data_o,
  output logic        obs_rx_valid_o,   // a received tape frame (not a realtime byte)
  output logic [interp_pkg::RealtimeCommands-1:0] obs_realtime_o,  // a realtime command
  output logic [7:0]  board_error_code_o
);

  // The status line's fields: N, and X, Y, the frame offset (sc_model/board/status_text.h).
  localparam int BlockWidth = 4 * interp_pkg::StatusBlockDigits;
  localparam int FieldWidth = 4 * interp_pkg::StatusDigits;

  logic [7:0]             rx_data, fifo_data;
  logic                   rx_valid, rx_ferr, fifo_valid, fifo_ready, overflow;
  // host_link's: the received byte is a frame, a command, a lone realtime byte, an ACK to
  // send (ack), sent (ack_sent).
  logic                   rx_frame, lone, ack, ack_sent;
  logic [interp_pkg::RealtimeCommands-1:0] command;
  logic [FifoAddrWidth:0] stored, level;
  logic [FieldWidth-1:0]  written;
  logic                   frame_ready, frame_valid, eot;
  logic                   overrun_x, overrun_y;
  logic                   i_step_x, i_dir_x, i_step_y, i_dir_y, i_busy, i_done, i_error, i_sat;
  logic [PosWidth-1:0]    i_pos_x, i_pos_y;
  logic [OffsetWidth-1:0] i_error_offset;
  logic [SeqWidth-1:0]    i_block_n, i_error_block;
  logic [interp_pkg::ErrCodeWidth-1:0] i_error_code;
  logic                   i_tool, i_paused;

  // tape_end_q: the EOT frame has been read. xoff_q: the host has been asked to stop.
  // cts_n_q: CTS# to the host. board_err_q: board error code.
  logic                   tape_end_q, xoff_q, cts_n_q;
  logic [7:0]             board_err_q;

  uart_rx #(.DivWidth(DivWidth)) u_rx (
    .clk_i, .rst_ni, .bit_cycles_i, .rx_i,
    .data_o(rx_data), .valid_o(rx_valid), .frame_error_o(rx_ferr)
  );

  if (RealtimeBytes) begin : g_realtime
    host_link u_link (
      .clk_i, .rst_ni, .rx_data_i(rx_data), .rx_valid_i(rx_valid),
      .taken_i(fifo_valid && fifo_ready), .ack_sent_i(ack_sent),
      .frame_o(rx_frame), .command_o(command), .lone_o(lone), .ack_o(ack)
    );
  end else begin : g_no_realtime
    assign rx_frame = 1'b1;
    assign command  = '0;
    assign {lone, ack} = '0;
    logic unused_ack_sent;  // never, with ack low
    assign unused_ack_sent = ack_sent;
  end

  // After a board error no byte is taken: the error line's offset stays the bytes
  // written before it.
  byte_fifo #(.AddrWidth(FifoAddrWidth), .CountWidth(FieldWidth)) u_fifo (
    .clk_i, .rst_ni, .in_data_i(rx_data), .in_valid_i(rx_valid && rx_frame && board_err_q == '0),
    .out_data_o(fifo_data), .out_valid_o(fifo_valid), .out_ready_i(fifo_ready),
    .stored_o(stored), .level_o(level), .written_o(written), .overflow_o(overflow)
  );

  // value >= bound for a constant bound, as gates: synthesis makes a carry chain of a
  // compare, which a constant does not shrink.
  function automatic logic at_least(input logic [FifoAddrWidth:0] value, input int bound);
    at_least = 1'b1;
    for (int i = 0; i <= FifoAddrWidth; i++) begin
      if (bound[i]) at_least = value[i] && at_least;
      else at_least = value[i] || at_least;
    end
  endfunction

  // The EOT frame is taken by the board, never shown to the decoder.
  assign eot         = fifo_valid && fifo_data == interp_pkg::LinkEndOfTape;
  assign frame_valid = fifo_valid && !eot && !tape_end_q;
  assign fifo_ready  = eot || (frame_ready && !tape_end_q);

  logic op_hold, op_start, op_estop, op_limit_x, op_limit_y, op_optional_stop;
  logic [interp_pkg::OverrideWidth-1:0] op_feed_override, op_rapid_override;
  if (OperatorPins) begin : g_pins
    operator_pins #(.DebounceWidth(DebounceWidth)) u_pins (
      .clk_i, .rst_ni, .hold_i, .start_i, .feed_up_i, .feed_down_i, .feed_reset_i, .rapid_cycle_i,
      .estop_i, .limit_x_i, .limit_y_i, .optional_stop_i, .remote_i(command),
      .hold_o(op_hold), .start_o(op_start), .feed_override_o(op_feed_override),
      .rapid_override_o(op_rapid_override), .estop_o(op_estop), .limit_x_o(op_limit_x),
      .limit_y_o(op_limit_y), .optional_stop_o(op_optional_stop)
    );
  end else begin : g_no_pins
    assign {op_hold, op_estop, op_limit_x, op_limit_y, op_optional_stop} = '0;
    assign op_start = 1'b1;
    assign op_feed_override = interp_pkg::OverrideOne;
    assign op_rapid_override = interp_pkg::OverrideOne;
    logic unused_pins;
    assign unused_pins = &{1'b0, hold_i, start_i, feed_up_i, feed_down_i, feed_reset_i, rapid_cycle_i,
                           estop_i, limit_x_i, limit_y_i, optional_stop_i, command};
  end

  interp_top #(
    .BitSerial(BitSerial), .CircleMode(CircleMode), .PosWidth(PosWidth), .SeqWidth(SeqWidth),
    .OffsetWidth(OffsetWidth), .ModulusWidth(ModulusWidth), .Accel(Accel),
    .MiscFunctions(MiscFunctions)
  ) u_interp (
    .clk_i, .rst_ni,
    .feed_modulus_i, .rapid_step_i, .accel_step_i, .hold_i(op_hold), .start_i(op_start),
    .feed_override_i(op_feed_override), .rapid_override_i(op_rapid_override),
    .estop_i(op_estop), .limit_x_i(op_limit_x), .limit_y_i(op_limit_y),
    .optional_stop_i(op_optional_stop),
    .frame_i(fifo_data), .frame_valid_i(frame_valid), .tape_end_i(tape_end_q),
    .frame_ready_o(frame_ready),
    .step_x_o(i_step_x), .dir_x_o(i_dir_x), .step_y_o(i_step_y), .dir_y_o(i_dir_y),
    .pos_x_o(i_pos_x), .pos_y_o(i_pos_y),
    .block_n_o(i_block_n), .busy_o(i_busy), .done_o(i_done), .error_o(i_error),
    .error_code_o(i_error_code), .error_block_o(i_error_block),
    .error_offset_o(i_error_offset), .feed_saturated_o(i_sat), .tool_o(i_tool),
    .paused_o(i_paused)
  );

  step_stretcher #(.CountWidth(StretchWidth)) u_stretch_x (
    .clk_i, .rst_ni, .setup_cycles_i, .pulse_cycles_i, .low_cycles_i,
    .step_i(i_step_x), .dir_i(i_dir_x), .step_o(step_x_o), .dir_o(dir_x_o),
    .overrun_o(overrun_x)
  );

  step_stretcher #(.CountWidth(StretchWidth)) u_stretch_y (
    .clk_i, .rst_ni, .setup_cycles_i, .pulse_cycles_i, .low_cycles_i,
    .step_i(i_step_y), .dir_i(i_dir_y), .step_o(step_y_o), .dir_o(dir_y_o),
    .overrun_o(overrun_y)
  );

  // The status line's fields: N, X, Y and the offsets modulo 2^FieldWidth (their low bits;
  // the host resolves them, sc_model/board/status_text.h), so synthesis keeps only those
  // bits of the interpolator's counters and registers that feed nothing else.
  logic                  any_error;
  logic [7:0]            line_code;
  logic [BlockWidth-1:0] line_block;
  logic [FieldWidth-1:0] line_offset;
  assign any_error   = i_error || board_err_q != '0;
  assign line_code   = board_err_q != '0 ? board_err_q : 8'(i_error_code);
  assign line_block  = BlockWidth'(board_err_q != '0 ? i_block_n : i_error_block);
  assign line_offset = board_err_q != '0 ? written : FieldWidth'(i_error_offset);

  status_line #(.DivWidth(DivWidth), .BlockWidth(BlockWidth), .FieldWidth(FieldWidth)) u_status (
    .clk_i, .rst_ni, .bit_cycles_i, .moved_i(i_step_x || i_step_y),
    .block_n_i(BlockWidth'(i_block_n)), .pos_x_i(FieldWidth'(i_pos_x)),
    .pos_y_i(FieldWidth'(i_pos_y)), .done_i(i_done), .error_i(any_error),
    .error_code_i(line_code), .error_block_i(line_block), .error_offset_i(line_offset),
    .xoff_i(xoff_q), .ack_i(ack), .ack_sent_o(ack_sent), .tx_o
  );

  always_ff @(posedge clk_i) begin
    if (!rst_ni) begin
      tape_end_q  <= 1'b0;
      xoff_q      <= 1'b0;
      cts_n_q     <= 1'b1;
      board_err_q <= '0;
    end else begin
      if (eot) tape_end_q <= 1'b1;
      if (at_least(stored, XoffLevel)) xoff_q <= 1'b1;
      else if (!at_least(stored, XonLevel + 1)) xoff_q <= 1'b0;
      cts_n_q <= at_least(stored, CtsStopLevel);
      // The first board error is kept, unless the interpolator stopped on one before: the
      // status line reports the first error.
      if (board_err_q == '0 && !i_error) begin
        if (overflow) board_err_q <= interp_pkg::BoardErrFifoOverflow;
        else if (rx_ferr) board_err_q <= interp_pkg::BoardErrFraming;
        else if (lone) board_err_q <= interp_pkg::BoardErrLoneRealtime;
        else if (overrun_x || overrun_y) board_err_q <= interp_pkg::BoardErrStepOverrun;
      end
    end
  end

  assign cts_no      = cts_n_q;
  assign led_busy_o  = i_busy;
  assign led_done_o  = i_done;
  assign led_error_o = any_error;
  assign tool_o      = i_tool;

  assign obs_frame_ready_o    = frame_ready;
  assign obs_step_x_o         = i_step_x;
  assign obs_dir_x_o          = i_dir_x;
  assign obs_step_y_o         = i_step_y;
  assign obs_dir_y_o          = i_dir_y;
  assign obs_pos_x_o          = i_pos_x;
  assign obs_pos_y_o          = i_pos_y;
  assign obs_block_n_o        = i_block_n;
  assign obs_busy_o           = i_busy;
  assign obs_done_o           = i_done;
  assign obs_error_o          = i_error;
  assign obs_error_code_o     = i_error_code;
  assign obs_error_block_o    = i_error_block;
  assign obs_error_offset_o   = i_error_offset;
  assign obs_feed_saturated_o = i_sat;
  assign obs_tool_o           = i_tool;
  assign obs_paused_o         = i_paused;
  assign obs_fifo_level_o     = level;
  assign obs_rx_data_o        = rx_data;
  assign obs_rx_valid_o       = rx_valid && rx_frame;
  assign obs_realtime_o       = command;
  assign board_error_code_o   = board_err_q;

endmodule
