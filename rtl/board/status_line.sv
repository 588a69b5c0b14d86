// Status lines and XON/XOFF on the board's UART TX line.
//
// What: one plain-ASCII line at every block end, at the end of the program and on an
// error, all with one layout (interp_pkg::Status*, from sw/host/tape/board_link.def): a
// kind letter and three fields of StatusDigits hex digits, then CR LF (21 characters with
// 5 digits), so the hardware needs no binary-to-decimal conversion; `ncinterp send` shows
// them in mm:
//   "B NNNNN XXXXX YYYYY"  block N ended; X, Y: position, BLU, two's complement
//   "D NNNNN XXXXX YYYYY"  program done (M02/M30 and tape end); last block N
//   "E NNNNN OOOOO CCCCC"  error in block N at frame offset O, code C
// A line takes 21 character times (1.8 ms at 115200 baud); block ends that come faster
// are merged: the next line reports the latest ended block and the position when the line
// starts. The error line and the done line are sent once each, after a pending block line.
// Flow control has priority: when xoff_i changes, XOFF or XON goes out before the next
// character of a line.
// Idea (lean): the three fields are copied into one shift register when the line starts
// and leave it a hex digit at a time, most significant first, so no multiplexer picks a
// digit out of the fields.
// Timing: a block ends at the edge where busy falls or block_n changes while busy (a new
// block loaded); the line's fields are copied at the edge where it starts.
// Golden twin: sc_model/board/status_text.h parses what it sends; the board's lock-step
// test (tests/sc_model/board) and the pty tests read its lines.
module status_line #(
  parameter int DivWidth   = 16,
  // One field: StatusDigits hex digits.
  parameter int FieldWidth = 4 * interp_pkg::StatusDigits
) (
  input  logic                  clk_i,
  input  logic                  rst_ni,
  input  logic [DivWidth-1:0]   bit_cycles_i,
  input  logic [FieldWidth-1:0] block_n_i,
  input  logic                  busy_i,
  input  logic                  done_i,
  input  logic                  error_i,
  input  logic [7:0]            error_code_i,
  input  logic [FieldWidth-1:0] error_block_i,
  input  logic [FieldWidth-1:0] error_offset_i,
  input  logic [FieldWidth-1:0] pos_x_i,
  input  logic [FieldWidth-1:0] pos_y_i,
  input  logic                  xoff_i,
  output logic                  tx_o
);

  localparam int Digits = interp_pkg::StatusDigits;
  // "K" and three times " " and the digits, then CR LF.
  localparam int LineLength = 1 + 3 * (1 + Digits) + 2;
  localparam int IndexWidth = $clog2(LineLength);

  // Events: busy_q / n_q last clock's busy and block_n; ended_n_q the latest ended block.
  logic                  busy_q, done_q, error_q;
  logic [FieldWidth-1:0] n_q, ended_n_q;
  logic                  pend_block_q, pend_done_q, pend_error_q;
  // The line being sent: active_q, its character index, its kind letter and the fields
  // still to send (the next digit in the top four bits).
  logic                    active_q;
  logic [IndexWidth-1:0]   index_q;
  logic [7:0]              kind_q;
  logic [3*FieldWidth-1:0] fields_q;
  // told_xoff_q: the host was last sent XOFF.
  logic                    told_xoff_q;

  logic       block_end, start_line, flow_byte, tx_ready, tx_valid, line_taken, space, digit;
  logic [7:0] tx_data, line_char;
  logic [3:0] nibble;

  uart_tx #(.DivWidth(DivWidth)) u_tx (
    .clk_i, .rst_ni, .bit_cycles_i, .data_i(tx_data), .valid_i(tx_valid),
    .ready_o(tx_ready), .tx_o
  );

  // Index 0 is the kind; a space opens each field (1, 1 + (1 + Digits), ...); CR LF end it.
  always_comb begin
    space = 1'b0;
    for (int f = 0; f < 3; f++) space |= index_q == IndexWidth'(1 + f * (1 + Digits));
  end
  assign digit  = index_q != '0 && !space && index_q < IndexWidth'(LineLength - 2);
  assign nibble = fields_q[3*FieldWidth-1 -: 4];
  always_comb begin
    if (index_q == '0) line_char = kind_q;
    else if (space) line_char = 8'h20;
    else if (digit) line_char = nibble < 4'd10 ? 8'h30 + {4'd0, nibble} : 8'h37 + {4'd0, nibble};
    else if (index_q == IndexWidth'(LineLength - 2)) line_char = 8'h0d;
    else line_char = 8'h0a;
  end

  assign block_end  = busy_q && (!busy_i || block_n_i != n_q);
  assign flow_byte  = xoff_i != told_xoff_q;
  assign start_line = !active_q && (pend_block_q || pend_error_q || pend_done_q);
  assign tx_valid   = flow_byte || active_q;
  assign tx_data    = flow_byte ? (xoff_i ? interp_pkg::LinkXoff : interp_pkg::LinkXon) : line_char;
  assign line_taken = active_q && tx_ready && !flow_byte;

  always_ff @(posedge clk_i) begin
    if (!rst_ni) begin
      busy_q       <= 1'b0;
      done_q       <= 1'b0;
      error_q      <= 1'b0;
      n_q          <= '0;
      ended_n_q    <= '0;
      pend_block_q <= 1'b0;
      pend_done_q  <= 1'b0;
      pend_error_q <= 1'b0;
      active_q     <= 1'b0;
      index_q      <= '0;
      kind_q       <= 8'h20;
      fields_q     <= '0;
      told_xoff_q  <= 1'b0;
    end else begin
      busy_q  <= busy_i;
      done_q  <= done_i;
      error_q <= error_i;
      n_q     <= block_n_i;
      if (block_end) ended_n_q <= n_q;
      if (tx_ready && flow_byte) told_xoff_q <= xoff_i;
      if (start_line) begin
        active_q <= 1'b1;
        index_q  <= '0;
        if (pend_block_q) begin
          kind_q   <= interp_pkg::StatusBlock;
          fields_q <= {ended_n_q, pos_x_i, pos_y_i};
        end else if (pend_error_q) begin
          kind_q   <= interp_pkg::StatusError;
          fields_q <= {error_block_i, error_offset_i, FieldWidth'(error_code_i)};
        end else begin
          kind_q   <= interp_pkg::StatusDone;
          fields_q <= {ended_n_q, pos_x_i, pos_y_i};
        end
      end else if (line_taken) begin
        index_q <= index_q + 1'b1;
        if (digit) fields_q <= fields_q << 4;
        if (index_q == IndexWidth'(LineLength - 1)) active_q <= 1'b0;
      end
      // Pending events: set by the event, cleared when their line starts.
      pend_block_q <= (pend_block_q && !start_line) || block_end;
      pend_error_q <= (pend_error_q && !(start_line && !pend_block_q)) || (error_i && !error_q);
      pend_done_q  <= (pend_done_q && !(start_line && !pend_block_q && !pend_error_q)) ||
                      (done_i && !done_q);
    end
  end

endmodule
