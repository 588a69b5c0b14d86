// Status lines, XON/XOFF and ACK on the board's UART TX line (8N1), with their transmitter.
//
// What: fixed-layout lines (interp_pkg::Status*, from sw/host/tape/board_link.def): a kind
// letter, a block field of StatusBlockDigits digits, two fields of StatusDigits digits,
// then CR LF (11 characters with 2 and 3 digits). A digit is one nibble sent as the
// character 0x30 + nibble ('0'..'9', ':'..'?' for 10..15), most significant first, so the
// hardware needs no conversion; `ncinterp send` shows the lines in mm and words
// (sc_model/board/status_text.h):
//   "BNNXXXYYY"  the machine has moved: block N playing (the last played when idle),
//                X, Y the position (BLU, two's complement)
//   "DNNXXXYYY"  program done (M02/M30 and tape end): the last block N, X, Y
//   "ENNOOOCCC"  error in block N at frame offset O, code C
// Each field is the low bits of its value (4 per digit); the host, which sent the tape
// and reads every line, resolves them (positions by continuity, N by the tape's blocks,
// offsets by the frames sent). A B line starts whenever the line is free and a step has
// been made since the last line started, so while the machine moves the host gets its
// block and position every line time (0.95 ms at 115 200 baud) and after it stops one line
// with the final position; blocks shorter than a line time are not seen (the host names
// the block ends it sees). The error line and the done line are sent once each, the error
// line first; a line that starts takes the place of any pending B line (each carries N and
// the position, the E line N). No character of a line is XON, XOFF, ACK, CR or LF but its
// end.
// Flow control has priority: when xoff_i changes, XOFF or XON goes out before the next
// character of a line, and then, while ack_i asks, an ACK (character counting, host_link.sv;
// ack_sent_o at its first clock).
// Idea (lean): one shift register holds N, X and Y, copied when a line starts, each nibble
// bit-reversed, and moves one place per bit sent of a digit, so the bit on the line is its
// top bit: no multiplexer picks a digit out of moving fields, no transmitter holds a copy
// of the character, and no register remembers past blocks (the host tells the blocks
// apart). A character's other bits are constants of its kind. The error line's offset and
// code do not move once the error is raised (the board freezes its byte count, the
// interpolator its error outputs): their bits are picked by the character and bit index.
// Timing: the line's fields are copied at the edge where it starts; a character starts at
// the next edge where no character is on the line (back to back); each bit lasts
// bit_cycles_i clocks; tx_o is a register (the bit one clock late).
// Golden twin: none of its own; sc_model/board/status_text.h parses what it sends, and the
// pty tests (tests/cli/test_board_cli.cpp) read its lines through the board simulation,
// whose host side receives them with the UART receiver's twin.
module status_line #(
  parameter int DivWidth   = 16,
  // The block field: StatusBlockDigits nibbles; the others StatusDigits nibbles.
  parameter int BlockWidth = 4 * interp_pkg::StatusBlockDigits,
  parameter int FieldWidth = 4 * interp_pkg::StatusDigits
) (
  input  logic                  clk_i,
  input  logic                  rst_ni,
  input  logic [DivWidth-1:0]   bit_cycles_i,
  // A step was made at this edge (either axis).
  input  logic                  moved_i,
  input  logic [BlockWidth-1:0] block_n_i,
  input  logic [FieldWidth-1:0] pos_x_i,
  input  logic [FieldWidth-1:0] pos_y_i,
  input  logic                  done_i,
  // error_i: stopped on an error; its code, block and offset (static while error_i).
  input  logic                  error_i,
  input  logic [7:0]            error_code_i,
  input  logic [BlockWidth-1:0] error_block_i,
  input  logic [FieldWidth-1:0] error_offset_i,
  input  logic                  xoff_i,
  input  logic                  ack_i,
  output logic                  ack_sent_o,
  output logic                  tx_o
);

  localparam int BlockDigits = BlockWidth / 4;
  localparam int Digits      = FieldWidth / 4;
  // The kind, the fields' digits, CR LF.
  localparam int LastDigit   = BlockDigits + 2 * Digits;
  localparam int LineLength  = 1 + LastDigit + 2;
  localparam int IndexWidth  = $clog2(LineLength);
  localparam int Fields      = BlockWidth + 2 * FieldWidth;

  // Events: error_q / done_q last clock's inputs; moved_q a step since the last line.
  logic                  done_q, error_q, moved_q;
  logic                  pend_done_q, pend_error_q;
  // The line: active_q, the index of its character to send, its kind (error_line_q, or
  // done: done_line_q) and the fields still to send (the next bit on top).
  logic                  active_q, error_line_q, done_line_q;
  logic [IndexWidth-1:0] index_q;
  logic [Fields-1:0]     fields_q;
  // The character on the line (sending_q): bit_q 0 the start bit, 1..8 the data bits, 9
  // the stop bit; count_q clocks left of the bit; flow_q it is XON/XOFF (told_xoff_q) or,
  // with ack_q, ACK.
  logic                  sending_q, flow_q, ack_q, told_xoff_q, tx_q;
  logic [3:0]            bit_q;
  logic [DivWidth-1:0]   count_q;

  logic                  start_line, start_error, start_done, flow_change, flow_byte, char_start;
  logic                  bit_end;
  logic                  shift;
  logic                  digit, digit_low, from_error, data_bit, line_bit;
  logic [2:0]            data_index;
  logic [7:0]            fixed_char;
  logic [3:0]            error_nibble;

  // Nibbles bit-reversed, so the shift register's top bit is the next one sent (LSB first).
  function automatic logic [Fields-1:0] reverse_nibbles(input logic [Fields-1:0] v);
    for (int i = 0; i < Fields; i += 4) reverse_nibbles[i +: 4] = {v[i], v[i+1], v[i+2], v[i+3]};
  endfunction

  // index_q >= bound for a constant bound, as gates (a compare would be a carry chain).
  function automatic logic index_at_least(input logic [IndexWidth-1:0] index, input int bound);
    index_at_least = 1'b1;
    for (int i = 0; i < IndexWidth; i++) begin
      if (bound[i]) index_at_least = index[i] && index_at_least;
      else index_at_least = index[i] || index_at_least;
    end
  endfunction

  // The character at index_q: the kind (0), a digit (1 .. LastDigit), CR, LF; a digit's
  // low four data bits (bit_q 1 .. 4) come from the fields.
  assign digit      = index_q != '0 && !index_at_least(index_q, LastDigit + 1);
  assign data_index = 3'(bit_q - 4'd1);
  assign digit_low  = !flow_q && digit && !bit_q[3] && (bit_q[2] ? bit_q[1:0] == 2'd0 : bit_q[1:0] != 2'd0);
  always_comb begin
    if (flow_q) fixed_char = ack_q ? interp_pkg::LinkAck :
                             told_xoff_q ? interp_pkg::LinkXoff : interp_pkg::LinkXon;
    else if (index_q == '0) fixed_char = error_line_q ? interp_pkg::StatusError :
                                         done_line_q ? interp_pkg::StatusDone :
                                         interp_pkg::StatusBlock;
    else if (digit) fixed_char = 8'h30;  // its low nibble is the digit
    else if (index_q == IndexWidth'(LineLength - 2)) fixed_char = 8'h0d;
    else fixed_char = 8'h0a;
  end

  // The E line's second and third fields: the offset's digits, then the code's (two
  // digits, zero-extended to the field).
  always_comb begin
    error_nibble = '0;
    for (int d = 0; d < Digits; d++) begin
      if (index_q == IndexWidth'(1 + BlockDigits + d))
        error_nibble = error_offset_i[4 * (Digits - 1 - d) +: 4];
    end
    if (index_q == IndexWidth'(LastDigit - 1)) error_nibble = error_code_i[7:4];
    if (index_q == IndexWidth'(LastDigit)) error_nibble = error_code_i[3:0];
  end
  assign from_error = error_line_q && index_at_least(index_q, BlockDigits + 1);

  assign data_bit = !digit_low ? fixed_char[data_index]
                  : from_error ? error_nibble[data_index[1:0]] : fields_q[Fields-1];
  // The start bit, the data bits, the stop bit; idle high.
  assign line_bit = !sending_q || bit_q == 4'd9 || (bit_q != '0 && data_bit);

  // The next line: an error, the end, or a move; the next character: XON/XOFF first, then
  // ACK.
  assign start_line  = !active_q && (pend_error_q || pend_done_q || moved_q);
  assign start_error = start_line && pend_error_q;
  assign start_done  = start_line && !pend_error_q && pend_done_q;
  assign flow_change = xoff_i != told_xoff_q;
  assign flow_byte   = flow_change || ack_i;
  assign ack_sent_o  = !sending_q && !flow_change && ack_i;
  assign char_start  = !sending_q && (flow_byte || active_q);
  assign bit_end     = sending_q && count_q == '0;
  assign shift       = bit_end && digit_low;

  // The fields: copied when a line starts, one place on after each digit bit sent.
  always_ff @(posedge clk_i) begin
    if (!rst_ni) fields_q <= '0;
    else if (start_line) fields_q <= reverse_nibbles({start_error ? error_block_i : block_n_i,
                                                      pos_x_i, pos_y_i});
    else if (shift) fields_q <= fields_q << 1;
  end

  always_ff @(posedge clk_i) begin
    if (!rst_ni) begin
      done_q       <= 1'b0;
      error_q      <= 1'b0;
      moved_q      <= 1'b0;
      pend_done_q  <= 1'b0;
      pend_error_q <= 1'b0;
      active_q     <= 1'b0;
      error_line_q <= 1'b0;
      done_line_q  <= 1'b0;
      index_q      <= '0;
      sending_q    <= 1'b0;
      flow_q       <= 1'b0;
      ack_q        <= 1'b0;
      told_xoff_q  <= 1'b0;
      bit_q        <= '0;
      count_q      <= '0;
      tx_q         <= 1'b1;
    end else begin
      done_q  <= done_i;
      error_q <= error_i;
      tx_q    <= line_bit;
      if (start_line) begin
        active_q     <= 1'b1;
        index_q      <= '0;
        error_line_q <= start_error;
        done_line_q  <= start_done;
      end
      if (char_start) begin
        sending_q <= 1'b1;
        flow_q    <= flow_byte;
        ack_q     <= ack_sent_o;
        if (flow_change) told_xoff_q <= xoff_i;
        bit_q     <= '0;
        count_q   <= bit_cycles_i - 1'b1;
      end else if (sending_q) begin
        if (!bit_end) begin
          count_q <= count_q - 1'b1;
        end else begin
          count_q <= bit_cycles_i - 1'b1;
          bit_q   <= bit_q + 1'b1;
          if (bit_q == 4'd9) begin
            sending_q <= 1'b0;
            if (!flow_q) begin
              index_q <= index_q + 1'b1;
              if (index_q == IndexWidth'(LineLength - 1)) active_q <= 1'b0;
            end
          end
        end
      end
      // Pending events: set by the event, cleared when their line starts (a move by any).
      moved_q      <= (moved_q && !start_line) || moved_i;
      pend_error_q <= (pend_error_q && !start_error) || (error_i && !error_q);
      pend_done_q  <= (pend_done_q && !start_done) || (done_i && !done_q);
    end
  end

  assign tx_o = tx_q;

endmodule
