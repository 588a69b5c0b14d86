// Formal harness: the reset values of every interp_top output (docs/interpolator.md 2).
//
// What is proven: after the reset edge frame_ready_o = 1 and every other output is 0, and
// this holds for any inputs during and after the reset clock (the outputs are registers).
// The default parameters are used: the property concerns one edge, so the 2-step BMC is a
// complete proof.
module interp_top_reset_props (
  input logic        clk_i,
  input logic [47:0] feed_modulus_i,
  input logic [47:0] rapid_step_i,
  input logic [7:0]  frame_i,
  input logic        frame_valid_i,
  input logic        tape_end_i
);

  logic f_init = 1'b1;
  always_ff @(posedge clk_i) f_init <= 1'b0;

  logic        frame_ready, step_x, dir_x, step_y, dir_y, busy, done, error, saturated, tool, paused;
  logic [31:0] pos_x, pos_y, error_offset;
  logic [19:0] block_n, error_block;
  logic [interp_pkg::ErrCodeWidth-1:0] error_code;

  interp_top u_dut (
    .clk_i, .rst_ni(!f_init), .feed_modulus_i, .rapid_step_i, .accel_step_i(48'd0), .hold_i(1'b0), .start_i(1'b0),
    .feed_override_i(interp_pkg::OverrideOne), .rapid_override_i(interp_pkg::OverrideOne),
    .estop_i(1'b0), .limit_x_i(1'b0), .limit_y_i(1'b0), .optional_stop_i(1'b0), .frame_i, .frame_valid_i, .tape_end_i,
    .frame_ready_o(frame_ready), .step_x_o(step_x), .dir_x_o(dir_x), .step_y_o(step_y),
    .dir_y_o(dir_y), .pos_x_o(pos_x), .pos_y_o(pos_y), .block_n_o(block_n), .busy_o(busy),
    .done_o(done), .error_o(error), .error_code_o(error_code), .error_block_o(error_block),
    .error_offset_o(error_offset), .feed_saturated_o(saturated), .tool_o(tool),
    .paused_o(paused)
  );

  always_comb begin
    if (!f_init) begin
      ap_reset_ready: assert (frame_ready);
      ap_reset_axes: assert (!step_x && !dir_x && !step_y && !dir_y && pos_x == '0 && pos_y == '0);
      ap_reset_status: assert (block_n == '0 && !busy && !done && !error && !saturated && !tool &&
                               !paused);
      ap_reset_error_report: assert (error_code == '0 && error_block == '0 && error_offset == '0);
    end
  end

  always_comb if (!f_init) cp_after_reset: cover (frame_ready);

endmodule
