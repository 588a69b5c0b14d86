// Status lines and XON/XOFF on the board's UART TX line.
//
// What: one plain-ASCII line of 30 characters at every block end, at the end of the
// program and on an error, all with the same layout (hex fields, so the hardware needs no
// binary-to-decimal conversion; `ncinterp send` shows them in mm):
//   "B 00 NNNNN XXXXXXXX YYYYYYYY\r\n"  block N ended; X, Y: position, BLU, two's complement
//   "D 00 NNNNN XXXXXXXX YYYYYYYY\r\n"  program done (M02/M30 and tape end); last block N
//   "E CC NNNNN OOOOOOOO 00000000\r\n"  error code CC in block N at frame offset O
// A line takes 30 character times (2.6 ms at 115200 baud); block ends that come faster
// are merged: the next line reports the latest ended block and the position when the
// line starts. The error line and the done line are sent once each, after a pending block
// line. Flow control has priority: when xoff_i changes, XOFF (0x13) or XON (0x11) goes out
// before the next character of a line.
// Timing: a block ends at the edge where busy falls or block_n changes while busy (a new
// block loaded); the line's fields are copied at the edge where it starts.
module status_line #(
  parameter int DivWidth = 16
) (
  input  logic                clk_i,
  input  logic                rst_ni,
  input  logic [DivWidth-1:0] bit_cycles_i,
  input  logic [19:0]         block_n_i,
  input  logic                busy_i,
  input  logic                done_i,
  input  logic                error_i,
  input  logic [7:0]          error_code_i,
  input  logic [19:0]         error_block_i,
  input  logic [31:0]         error_offset_i,
  input  logic [31:0]         pos_x_i,
  input  logic [31:0]         pos_y_i,
  input  logic                xoff_i,
  output logic                tx_o
);

  localparam logic [7:0] Xon = 8'h11, Xoff = 8'h13;
  localparam int LineLength = 30;

  // Events: busy_q / n_q last clock's busy and block_n; ended_n_q the latest ended block.
  logic        busy_q, done_q, error_q;
  logic [19:0] n_q, ended_n_q;
  logic        pend_block_q, pend_done_q, pend_error_q;
  // The line being sent: active_q, its character index, and its fields.
  logic        active_q;
  logic [4:0]  index_q;
  logic [7:0]  kind_q, code_q;
  logic [19:0] field_n_q;
  logic [31:0] field_a_q, field_b_q;
  // told_xoff_q: the host was last sent XOFF.
  logic        told_xoff_q;

  logic        block_end, start_line, flow_byte, tx_ready, tx_valid;
  logic [7:0]  tx_data, line_char;

  uart_tx #(.DivWidth(DivWidth)) u_tx (
    .clk_i, .rst_ni, .bit_cycles_i, .data_i(tx_data), .valid_i(tx_valid),
    .ready_o(tx_ready), .tx_o
  );

  function automatic logic [7:0] hex(input logic [3:0] v);
    hex = v < 4'd10 ? 8'h30 + {4'd0, v} : 8'h37 + {4'd0, v};
  endfunction

  always_comb begin
    unique case (index_q)
      5'd0: line_char = kind_q;
      5'd2: line_char = hex(code_q[7:4]);
      5'd3: line_char = hex(code_q[3:0]);
      5'd5, 5'd6, 5'd7, 5'd8, 5'd9:
        line_char = hex(field_n_q[4 * (9 - index_q) +: 4]);
      5'd11, 5'd12, 5'd13, 5'd14, 5'd15, 5'd16, 5'd17, 5'd18:
        line_char = hex(field_a_q[4 * (18 - index_q) +: 4]);
      5'd20, 5'd21, 5'd22, 5'd23, 5'd24, 5'd25, 5'd26, 5'd27:
        line_char = hex(field_b_q[4 * (27 - index_q) +: 4]);
      5'd28: line_char = 8'h0d;
      5'd29: line_char = 8'h0a;
      default: line_char = 8'h20;
    endcase
  end

  assign block_end  = busy_q && (!busy_i || block_n_i != n_q);
  assign flow_byte  = xoff_i != told_xoff_q;
  assign start_line = !active_q && (pend_block_q || pend_error_q || pend_done_q);
  assign tx_valid   = flow_byte || active_q;
  assign tx_data    = flow_byte ? (xoff_i ? Xoff : Xon) : line_char;

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
      code_q       <= '0;
      field_n_q    <= '0;
      field_a_q    <= '0;
      field_b_q    <= '0;
      told_xoff_q  <= 1'b0;
    end else begin
      busy_q  <= busy_i;
      done_q  <= done_i;
      error_q <= error_i;
      n_q     <= block_n_i;
      if (block_end) ended_n_q <= n_q;
      if (tx_ready && flow_byte) told_xoff_q <= xoff_i;
      if (start_line) begin
        active_q  <= 1'b1;
        index_q   <= '0;
        field_n_q <= ended_n_q;
        code_q    <= '0;
        field_a_q <= pos_x_i;
        field_b_q <= pos_y_i;
        if (pend_block_q) begin
          kind_q       <= "B";
        end else if (pend_error_q) begin
          kind_q    <= "E";
          code_q    <= error_code_i;
          field_n_q <= error_block_i;
          field_a_q <= error_offset_i;
          field_b_q <= '0;
        end else begin
          kind_q <= "D";
        end
      end else if (active_q && tx_ready && !flow_byte) begin
        index_q <= index_q + 1'b1;
        if (index_q == 5'(LineLength - 1)) active_q <= 1'b0;
      end
      // Pending events: set by the event, cleared when their line starts.
      pend_block_q <= (pend_block_q && !start_line) || block_end;
      pend_error_q <= (pend_error_q && !(start_line && !pend_block_q)) || (error_i && !error_q);
      pend_done_q  <= (pend_done_q && !(start_line && !pend_block_q && !pend_error_q)) ||
                      (done_i && !done_q);
    end
  end

endmodule
