// Byte FIFO between the UART receiver and the tape decoder (the board's tape buffer).
//
// What: 2^AddrWidth bytes of storage (one iCE40 block RAM at AddrWidth 8 or 9) plus an
// output register, so the head byte is offered on out_data_o / out_valid_o like a reader's
// frame (first-word fall-through). stored_o counts the bytes in the storage (the board's
// flow control compares it), level_o every byte held (storage + output register).
// written_o counts the bytes written, modulo 2^CountWidth (the write pointer is its low
// bits), so the board's error line needs no byte counter of its own. A byte written while
// the FIFO is full is dropped and raises overflow_o for one clock: flow control has
// failed (an error).
// Timing: the RAM is read synchronously into the output register when that register is
// empty or being taken, so a byte written at edge e is offered from edge e+2 on.
module byte_fifo #(
  parameter int AddrWidth  = 8,
  // written_o's width (> AddrWidth).
  parameter int CountWidth = AddrWidth + 1
) (
  input  logic               clk_i,
  input  logic               rst_ni,
  input  logic [7:0]         in_data_i,
  input  logic               in_valid_i,
  output logic [7:0]         out_data_o,
  output logic               out_valid_o,
  input  logic               out_ready_i,
  output logic [AddrWidth:0] stored_o,
  output logic [AddrWidth:0] level_o,
  output logic [CountWidth-1:0] written_o,
  output logic               overflow_o
);

  localparam int Depth = 1 << AddrWidth;

  logic [7:0]           mem_q [Depth];
  // wr_q / rd_q: RAM pointers with one wrap bit (wr_q's low bits of the bytes written);
  // out_q / out_valid_q: the output register.
  logic [CountWidth-1:0] wr_q;
  logic [AddrWidth:0]   rd_q, stored;
  logic [7:0]           out_q;
  logic                 out_valid_q, overflow_q, write, read;

  assign stored = wr_q[AddrWidth:0] - rd_q;
  assign write  = in_valid_i && stored != (AddrWidth + 1)'(Depth);
  assign read   = stored != '0 && (!out_valid_q || out_ready_i);

  always_ff @(posedge clk_i) begin
    if (write) mem_q[wr_q[AddrWidth-1:0]] <= in_data_i;
    if (read) out_q <= mem_q[rd_q[AddrWidth-1:0]];
  end

  always_ff @(posedge clk_i) begin
    if (!rst_ni) begin
      wr_q        <= '0;
      rd_q        <= '0;
      out_valid_q <= 1'b0;
      overflow_q  <= 1'b0;
    end else begin
      if (write) wr_q <= wr_q + 1'b1;
      if (read) rd_q <= rd_q + 1'b1;
      if (read) out_valid_q <= 1'b1;
      else if (out_ready_i) out_valid_q <= 1'b0;
      overflow_q <= in_valid_i && !write;
    end
  end

  assign out_data_o  = out_q;
  assign out_valid_o = out_valid_q;
  // The output register counts as one more place (level <= Depth + 1 fits AddrWidth + 1
  // bits only up to Depth, so the full RAM plus the register saturates at Depth).
  assign level_o     = (stored == (AddrWidth + 1)'(Depth)) ? stored : stored + (AddrWidth + 1)'(out_valid_q);
  assign stored_o    = stored;
  assign written_o   = wr_q;
  assign overflow_o  = overflow_q;

endmodule
