// UART transmitter, 8N1: the board's status lines and XON/XOFF back to the host.
//
// What: a byte offered on data_i / valid_i while ready_o is high is sent as a start bit,
// 8 data bits LSB first and a stop bit, each bit_cycles_i clocks long.
// Timing: the byte is taken at the edge where valid_i & ready_o; tx_o shows its start bit
// from that edge on and ready_o is high again after the edge that ends the stop bit, so
// back-to-back bytes leave no idle time between them. tx_o is a function of registers.
// Golden twin: sc_model/board/uart_tx_model.h (UartTxModel), compared every clock by
// tests/sc_model/board/test_board_lockstep.cpp.
module uart_tx #(
  parameter int DivWidth = 16
) (
  input  logic                clk_i,
  input  logic                rst_ni,
  input  logic [DivWidth-1:0] bit_cycles_i,
  input  logic [7:0]          data_i,
  input  logic                valid_i,
  output logic                ready_o,
  output logic                tx_o
);

  // shift_q: the bits still to send, LSB on the line; left_q: how many (0: idle);
  // count_q: clocks left of the current bit.
  logic [9:0]          shift_q;
  logic [3:0]          left_q;
  logic [DivWidth-1:0] count_q;

  always_ff @(posedge clk_i) begin
    if (!rst_ni) begin
      shift_q <= '1;
      left_q  <= '0;
      count_q <= '0;
    end else if (left_q == '0) begin
      if (valid_i) begin
        shift_q <= {1'b1, data_i, 1'b0};
        left_q  <= 4'd10;
        count_q <= bit_cycles_i - 1'b1;
      end
    end else if (count_q != '0) begin
      count_q <= count_q - 1'b1;
    end else begin
      shift_q <= {1'b1, shift_q[9:1]};
      left_q  <= left_q - 1'b1;
      count_q <= bit_cycles_i - 1'b1;
    end
  end

  assign ready_o = left_q == '0;
  assign tx_o    = left_q == '0 ? 1'b1 : shift_q[0];

endmodule
