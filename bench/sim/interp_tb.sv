// Icarus Verilog testbench of the simulation benchmark (bench/sim/sim_bench.cpp).
//
// What: plays a tape through interp_top with the same reader timing as FrameSource
// (sc_model/golden/frame_source.h): a frame becomes valid cycles_per_frame clocks after the
// previous one was taken and stays valid until frame_valid & frame_ready at an edge. Frames
// come from a hex file ($readmemh). Stops at done, error or +max_cycles and prints the
// cycle count and final position, which the benchmark checks against the golden model.
// Plusargs: +frames=FILE +nframes=N +cpf=C +modulus=M +rapid=R +max_cycles=K; the arch is the
// parameter BitSerial (iverilog -Pinterp_tb.BitSerial=0 for the parallel one).
`timescale 1ns / 1ps
module interp_tb #(
  parameter bit BitSerial = 1'b1
);
  localparam int MaxFrames = 1 << 20;

  logic [7:0] frames [MaxFrames];
  string      path;
  longint     nframes, cpf, modulus, rapid, max_cycles;

  logic        clk = 1'b0;
  logic        rst_n = 1'b0;
  // Reader: index of the frame under the head and clocks until it is readable.
  longint      next_frame = 0, countdown = 0, cycles = 0;
  logic [7:0]  frame;
  logic        frame_valid, tape_end, frame_ready;
  logic        step_x, dir_x, step_y, dir_y, busy, done, error, saturated, tool, paused;
  logic [31:0] pos_x, pos_y, error_offset;
  logic [19:0] block_n, error_block;
  logic [3:0]  error_code;

  assign frame_valid = next_frame < nframes && countdown == 0;
  assign frame       = frame_valid ? frames[next_frame] : 8'h00;
  assign tape_end    = next_frame >= nframes;

  interp_top #(.BitSerial(BitSerial)) dut (
    .clk_i(clk), .rst_ni(rst_n), .feed_modulus_i(modulus[47:0]), .rapid_step_i(rapid[47:0]), .accel_step_i(48'd0), .hold_i(1'b0), .start_i(1'b0),
    .feed_override_i(interp_pkg::OverrideOne), .rapid_override_i(interp_pkg::OverrideOne),
    .estop_i(1'b0), .limit_x_i(1'b0), .limit_y_i(1'b0), .optional_stop_i(1'b0),
    .frame_i(frame), .frame_valid_i(frame_valid), .tape_end_i(tape_end),
    .frame_ready_o(frame_ready),
    .step_x_o(step_x), .dir_x_o(dir_x), .step_y_o(step_y), .dir_y_o(dir_y),
    .pos_x_o(pos_x), .pos_y_o(pos_y), .block_n_o(block_n),
    .busy_o(busy), .done_o(done), .error_o(error), .error_code_o(error_code),
    .error_block_o(error_block), .error_offset_o(error_offset), .feed_saturated_o(saturated),
    .tool_o(tool), .paused_o(paused)
  );

  initial begin
    if (!$value$plusargs("frames=%s", path) || !$value$plusargs("nframes=%d", nframes) ||
        !$value$plusargs("cpf=%d", cpf) || !$value$plusargs("modulus=%d", modulus) ||
        !$value$plusargs("rapid=%d", rapid) ||
        !$value$plusargs("max_cycles=%d", max_cycles)) begin
      $display("usage: +frames=FILE +nframes=N +cpf=C +modulus=M +rapid=R +max_cycles=K");
      $finish;
    end
    if (nframes > 0) $readmemh(path, frames, 0, nframes - 1);
    countdown = cpf - 1;
  end

  always #1 clk = ~clk;

  // Reset for the first edge, then count edges; the reader advances as FrameSource does.
  always @(posedge clk) begin
    if (!rst_n) begin
      rst_n <= 1'b1;
    end else begin
      cycles <= cycles + 1;
      if (next_frame < nframes) begin
        if (countdown > 0) countdown <= countdown - 1;
        else if (frame_ready) begin
          next_frame <= next_frame + 1;
          countdown  <= cpf - 1;
        end
      end
    end
  end

  // Outputs of an edge are settled at the following falling edge.
  always @(negedge clk) begin
    if (rst_n && (done || error || cycles >= max_cycles)) begin
      $display("cycles %0d pos %0d %0d done %0d error %0d", cycles, $signed(pos_x),
               $signed(pos_y), done, error);
      $finish;
    end
  end
endmodule
