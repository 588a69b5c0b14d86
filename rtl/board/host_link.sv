// Host link: which received bytes are tape frames and which are realtime commands, and the
// acknowledgements of the tape bytes taken (character counting; docs/board.md "The link").
//
// What: a realtime byte (interp_pkg::Realtime*, sw/host/tape/board_link.def) has odd parity,
// which no tape frame has, and the host sends it twice, back to back. The first of a pair
// is held here (not a frame); the second, equal to it, gives the command: one clock of its
// bit of command_o (interp_pkg::realtime_command(), in operator_pins' order). A held byte
// followed by any other byte is lone: lone_o for one clock, the board's error
// BoardErrLoneRealtime, and that byte is not a frame either. Every other byte is a frame
// (frame_o, at the byte's clock, for the FIFO): an odd byte that is no command still goes
// to the tape reader, which finds its parity error. So one line error cannot turn a frame
// into a command unnoticed.
// The host keeps at most interp_pkg::LinkFifoBytes tape bytes unacknowledged. Here every
// LinkAckBytes bytes taken out of the FIFO (taken_i) make one ACK pending; ack_o asks the
// status line to send it, and ack_sent_i (the ACK's first clock on the line) takes one.
// The FIFO never holds more than LinkFifoBytes, so at most LinkFifoBytes / LinkAckBytes
// ACKs wait at any time, plus the one that may be on the line (a_acks_fit).
// Timing: frame_o is combinational from rx_valid_i and rx_data_i (the byte's clock);
// command_o and lone_o are registers (the clock after the pair's second byte).
// Golden twin: HostLinkModel (sc_model/board/host_link_model.h).
module host_link (
  input  logic       clk_i,
  input  logic       rst_ni,
  input  logic [7:0] rx_data_i,
  input  logic       rx_valid_i,
  input  logic       taken_i,      // a byte left the tape FIFO at this edge
  input  logic       ack_sent_i,   // the status line starts an ACK at this edge
  output logic       frame_o,      // rx_data_i is a tape frame (with rx_valid_i)
  output logic [interp_pkg::RealtimeCommands-1:0] command_o,
  output logic       lone_o,
  output logic       ack_o
);

  localparam int Commands  = interp_pkg::RealtimeCommands;
  localparam int ChunkBits = $clog2(interp_pkg::LinkAckBytes);
  localparam int MaxAcks   = interp_pkg::LinkFifoBytes / interp_pkg::LinkAckBytes + 1;
  localparam int AckBits   = $clog2(MaxAcks + 1);

  // held_q: the first byte of a pair, as its command bit.
  logic [Commands-1:0]  rx_command, held_q, command_q;
  logic                 lone_q;
  logic [ChunkBits-1:0] taken_q;   // bytes taken since the last ACK became pending
  logic [AckBits-1:0]   acks_q;    // ACKs pending
  logic                 chunk_done;

  assign rx_command = interp_pkg::realtime_command(rx_data_i);
  assign frame_o    = held_q == '0 && rx_command == '0;
  assign chunk_done = taken_i && &taken_q;

  always_ff @(posedge clk_i) begin
    if (!rst_ni) begin
      held_q    <= '0;
      command_q <= '0;
      lone_q    <= 1'b0;
      taken_q   <= '0;
      acks_q    <= '0;
    end else begin
      command_q <= '0;
      lone_q    <= 1'b0;
      if (rx_valid_i) begin
        if (held_q != '0) begin
          command_q <= held_q == rx_command ? held_q : '0;
          lone_q    <= held_q != rx_command;
          held_q    <= '0;
        end else begin
          held_q <= rx_command;
        end
      end
      taken_q <= taken_q + ChunkBits'(taken_i);
      acks_q  <= acks_q + AckBits'(chunk_done) - AckBits'(ack_sent_i);
    end
  end

  assign command_o = command_q;
  assign lone_o    = lone_q;
  assign ack_o     = acks_q != '0;

`ifndef SYNTHESIS
  // Checked at every edge of every verilated run: an ACK is sent only when one is pending,
  // and the pending ones fit their counter (the FIFO bounds them, above).
  always_ff @(posedge clk_i) begin
    if (rst_ni) begin
      a_ack_sent_pending: assert (!ack_sent_i || acks_q != '0);
      a_acks_fit: assert (acks_q <= AckBits'(MaxAcks));
    end
  end
`endif

endmodule
