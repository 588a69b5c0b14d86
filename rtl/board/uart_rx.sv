// UART receiver, 8N1: one received byte per valid_o pulse (the board's tape reader).
//
// What: a two-flop synchroniser on rx_i, then a start / 8 data (LSB first) / stop bit
// state machine that samples each bit in its middle: the start bit half a bit after the
// falling edge (and checks it is still low, else it was a glitch), every later bit one bit
// time (bit_cycles_i clocks) after the previous sample. A low stop bit is a framing error
// (frame_error_o pulse, the byte is dropped); the receiver then waits for the line to go
// high again, so a break (line held low) gives one error, not a stream of zero bytes.
// The receiver returns to idle in the middle of the stop bit, which leaves half a bit of
// margin for a sender whose clock is up to about 4 % off.
// Timing: data_o and valid_o are registers; valid_o is high for one clock, two clocks (the
// synchroniser) plus 9.5 bit times after the start edge. bit_cycles_i is static (a
// constant at the board top, a port so the simulation and the lock-step test can vary it);
// it must be at least 4.
// Golden twin: sc_model/board/uart_rx_model.h (UartRxModel), compared every clock by
// tests/sc_model/board/test_board_lockstep.cpp.
module uart_rx #(
  parameter int DivWidth = 16
) (
  input  logic                clk_i,
  input  logic                rst_ni,
  input  logic [DivWidth-1:0] bit_cycles_i,
  input  logic                rx_i,
  output logic [7:0]          data_o,
  output logic                valid_o,
  output logic                frame_error_o
);

  typedef enum logic [2:0] {StIdle, StStart, StData, StStop, StWaitHigh} state_e;

  // meta_q, sync_q: the synchroniser (idle line is high). state_q/count_q: where in the
  // frame and clocks to the next sample. bit_q: data bits sampled. shift_q: the byte.
  logic                meta_q, sync_q;
  state_e              state_q, state_d;
  logic [DivWidth-1:0] count_q, count_d;
  logic [2:0]          bit_q, bit_d;
  logic [7:0]          shift_q, shift_d;
  logic                valid_q, valid_d, ferr_q, ferr_d;

  always_comb begin
    state_d = state_q;
    count_d = count_q;
    bit_d   = bit_q;
    shift_d = shift_q;
    valid_d = 1'b0;
    ferr_d  = 1'b0;
    unique case (state_q)
      StIdle: if (!sync_q) begin
        state_d = StStart;
        count_d = (bit_cycles_i >> 1) - 1'b1;
      end
      StStart: if (count_q != '0) count_d = count_q - 1'b1;
               else if (sync_q) state_d = StIdle;  // a glitch, not a start bit
               else begin
                 state_d = StData;
                 count_d = bit_cycles_i - 1'b1;
                 bit_d   = '0;
               end
      StData: if (count_q != '0) count_d = count_q - 1'b1;
              else begin
                shift_d = {sync_q, shift_q[7:1]};
                count_d = bit_cycles_i - 1'b1;
                bit_d   = bit_q + 1'b1;
                if (bit_q == 3'd7) state_d = StStop;
              end
      StStop: if (count_q != '0) count_d = count_q - 1'b1;
              else if (sync_q) begin
                valid_d = 1'b1;
                state_d = StIdle;
              end else begin
                ferr_d  = 1'b1;
                state_d = StWaitHigh;
              end
      StWaitHigh: if (sync_q) state_d = StIdle;
      default: state_d = StIdle;
    endcase
  end

  always_ff @(posedge clk_i) begin
    if (!rst_ni) begin
      meta_q  <= 1'b1;
      sync_q  <= 1'b1;
      state_q <= StIdle;
      count_q <= '0;
      bit_q   <= '0;
      shift_q <= '0;
      valid_q <= 1'b0;
      ferr_q  <= 1'b0;
    end else begin
      meta_q  <= rx_i;
      sync_q  <= meta_q;
      state_q <= state_d;
      count_q <= count_d;
      bit_q   <= bit_d;
      shift_q <= shift_d;
      valid_q <= valid_d;
      ferr_q  <= ferr_d;
    end
  end

  assign data_o        = shift_q;
  assign valid_o       = valid_q;
  assign frame_error_o = ferr_q;

endmodule
