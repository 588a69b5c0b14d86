// Place-and-route harness of interp_top for the bit-width sweep's Fmax (nextpnr-ice40).
//
// What: interp_top with every parameter of the design point (passed through), its ports
// brought down to what a board has pins for (40 pins: fits the HX1K's TQ144 as well).
// interp_top has about 210 ports (48-bit feed modulus, two 32-bit positions, block and error
// registers), more than the HX8K's CT256 package can bond, so it cannot be placed as it
// is. Here the static feed modulus is shifted in serially (cfg_data_i / cfg_shift_i, as a
// machine's configuration switches would be read), and the wide status outputs are read out
// one byte at a time through a registered multiplexer (rd_sel_i -> rd_data_o). Every
// interp_top output stays observable, so synthesis removes nothing of the interpolator.
// Timing: the harness adds only registers at the edges (the modulus shift register, the
// read-out register), so the critical path nextpnr reports is the interpolator's own.
// Cost: ModulusWidth + 8 flip-flops and a small multiplexer; the sweep's area columns come
// from interp_top alone, this harness is used only for placement and Fmax.
module interp_fpga_top #(
  // interp_top's parameters, passed through (the sweep sets any of them with chparam).
  parameter int IncWidth       = 16,
  parameter int FracDigits     = 3,
  parameter int FeedWidth      = 32,
  parameter int FeedFracDigits = 3,
  parameter int PosWidth       = 32,
  parameter int SeqWidth       = 20,
  parameter int OffsetWidth    = 32,
  parameter int ModulusWidth   = 48,
  parameter bit BitSerial      = 1'b1,
  parameter bit CircleMode     = 1'b1
) (
  input  logic       clk_i,
  input  logic       rst_ni,
  input  logic       cfg_data_i,    // feed modulus, then the rapid step, shifted in MSB first
  input  logic       cfg_shift_i,
  input  logic [7:0] frame_i,
  input  logic       frame_valid_i,
  input  logic       tape_end_i,
  output logic       frame_ready_o,
  output logic       step_x_o,
  output logic       dir_x_o,
  output logic       step_y_o,
  output logic       dir_y_o,
  output logic       busy_o,
  output logic       done_o,
  output logic       error_o,
  output logic [interp_pkg::ErrCodeWidth-1:0] error_code_o,
  output logic       feed_saturated_o,
  output logic       tool_o,
  output logic       paused_o,
  input  logic [4:0] rd_sel_i,      // which byte of the status word
  output logic [7:0] rd_data_o
);

  localparam int StatusWidth  = 2 * PosWidth + 2 * SeqWidth + OffsetWidth;
  localparam int StatusBytes  = (StatusWidth + 7) / 8;

  // modulus_q, rapid_q: the feed modulus and the rapid step as shifted in (static while the
  // machine runs).
  logic [ModulusWidth-1:0] modulus_q, rapid_q;
  // rd_data_q: the selected byte of the status word, registered.
  logic [7:0]              rd_data_q;

  logic [PosWidth-1:0]    pos_x, pos_y;
  logic [SeqWidth-1:0]    block_n, error_block;
  logic [OffsetWidth-1:0] error_offset;
  logic [8*StatusBytes-1:0] status;

  interp_top #(
    .IncWidth(IncWidth), .FracDigits(FracDigits), .FeedWidth(FeedWidth),
    .FeedFracDigits(FeedFracDigits), .PosWidth(PosWidth), .SeqWidth(SeqWidth),
    .OffsetWidth(OffsetWidth), .ModulusWidth(ModulusWidth), .BitSerial(BitSerial),
    .CircleMode(CircleMode)
  ) u_interp (
    .clk_i, .rst_ni,
    .feed_modulus_i(modulus_q), .rapid_step_i(rapid_q), .accel_step_i('0), .hold_i(1'b0), .start_i(1'b0),
    .feed_override_i(interp_pkg::OverrideOne), .rapid_override_i(interp_pkg::OverrideOne),
    .estop_i(1'b0), .limit_x_i(1'b0), .limit_y_i(1'b0), .optional_stop_i(1'b0),
    .frame_i, .frame_valid_i, .tape_end_i, .frame_ready_o,
    .step_x_o, .dir_x_o, .step_y_o, .dir_y_o,
    .pos_x_o(pos_x), .pos_y_o(pos_y),
    .block_n_o(block_n), .busy_o, .done_o, .error_o, .error_code_o,
    .error_block_o(error_block), .error_offset_o(error_offset),
    .feed_saturated_o, .tool_o, .paused_o
  );

  assign status = (8 * StatusBytes)'({pos_x, pos_y, block_n, error_block, error_offset});

  always_ff @(posedge clk_i) begin
    if (cfg_shift_i) {modulus_q, rapid_q} <= {modulus_q[ModulusWidth-2:0], rapid_q, cfg_data_i};
    rd_data_q <= status[8 * rd_sel_i +: 8];
  end

  assign rd_data_o = rd_data_q;

endmodule
