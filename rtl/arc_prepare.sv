// Arc preparation in the decoder: checks an arc block and dry-runs its circle DDA.
//
// What: while the decoder holds a complete arc block (run_i), this module (a) checks it:
// zero radius, quadrant and register width at once (arc_geometry.sv), and the end's
// distance to the circle on a one-bit serial adder (arc_radius_check.sv, C = (5W + 4)
// (2W + 4) clocks); and (b) runs the block's circle DDA once without pulses and marks each
// iteration (iterate_o), at which the decoder adds F to the block's step: when both are
// over, S = F * N (N = the block's iteration count) goes with the block, and the feed
// generator plays the N iterations in M / F clocks, as it plays the 2^k iterations of a
// line (docs/circle-dda.md section 4). A failed radius check stops the dry run.
// The dry run is a second dda_circle, one iteration per clock (BitSerial = 0), or the
// bit-serial dda_serial.sv, 2P clocks per iteration (P = W rounded up to a power of two) for
// about 150 logic cells fewer: the trade of docs/interpolator.md 3.5. With BitSerial the
// geometry is bit-serial too, and the radius check, the serial dry run and the geometry read
// the words as they turn in the decoder (shift_o), bit 0 first: no multiplexers. The golden
// twin is sc_model/golden/arc_prepare.cpp.
// Timing: the first clock with run_i is the start edge (BitSerial: the geometry's serial
// pass takes that edge and W more, and the start edge is the one after them): a geometric
// error makes done_o high in that clock; otherwise the dry run and the check run from the
// next edges and done_o rises in the clock after the later of the two: max(N, C) clocks
// after the start edge, max(2PN, C) with BitSerial. done_o, the error and iterate_o are
// combinational from registers (and the held block); the decoder acts on them at that edge.
module arc_prepare #(
  parameter int IncWidth  = 16,
  parameter int KWidth    = $clog2(IncWidth + 1),
  parameter bit BitSerial = 1'b0
) (
  input  logic                 clk_i,
  input  logic                 rst_ni,
  input  logic                 run_i,       // the decoder holds an arc block
  input  logic [IncWidth-1:0]  dx_i,
  input  logic                 dx_neg_i,
  input  logic [IncWidth-1:0]  dy_i,
  input  logic                 dy_neg_i,
  input  logic [IncWidth-1:0]  i_i,
  input  logic                 i_neg_i,
  input  logic [IncWidth-1:0]  j_i,
  input  logic                 j_neg_i,
  input  logic                 ccw_i,
  output logic                 done_o,      // the result is final in this clock
  output logic                 err_o,       // ... and it is an error
  output logic [interp_pkg::ErrCodeWidth-1:0] err_code_o,
  output logic                 iterate_o,   // a dry-run iteration at this edge
  // The magnitudes of I, J, X, Y turn one place at this edge (the decoder's registers, bit
  // 0 first): the radius check and the dry run read them one bit per clock.
  output logic                 shift_o,
  // The arc's geometry for the player's circle DDA (valid in clocks with run_i).
  output logic [KWidth-1:0]    k_o,
  output logic                 grow_x_o,
  output logic                 grow_y_o
);


  // running_q: the arc's dry run and radius check are in progress (after the start edge).
  logic                 running_q, running_d;

  logic                start;
  logic                grow_x, grow_y, geo_err, add_x, add_y, geo_shift, geo_done;
  logic [interp_pkg::ErrCodeWidth-1:0] geo_code;
  logic [KWidth-1:0]   k;
  logic                dry_iterate, dry_done, check_done, check_ok, check_shift;

  // The check and the dry run start once the geometry is known (at once, or after its
  // serial pass).
  assign start = run_i && geo_done && !running_q;

  arc_geometry #(.IncWidth(IncWidth), .KWidth(KWidth), .BitSerial(BitSerial)) u_geometry (
    .clk_i, .rst_ni, .enable_i(run_i), .shift_o(geo_shift), .done_o(geo_done),
    .dx_i, .dx_neg_i, .dy_i, .dy_neg_i, .i_i, .i_neg_i, .j_i, .j_neg_i, .ccw_i,
    .grow_x_o(grow_x), .grow_y_o(grow_y), .add_x_o(add_x), .add_y_o(add_y),
    .k_o(k), .error_o(geo_err), .error_code_o(geo_code)
  );

  if (BitSerial) begin : g_serial_dry_run
    // The dry run emits no pulses and has no direction; the held block's words stay.
    /* verilator lint_off UNUSEDSIGNAL */
    logic dry_carry_x, dry_carry_y, dry_step_x, dry_step_y, dry_dir_x, dry_dir_y, dry_words;
    logic [$clog2(IncWidth)-1:0] dry_bit;
    /* verilator lint_on UNUSEDSIGNAL */
    // The dry run's first pass is the radius check's first: the words turn (shift_o) in
    // its clocks 0 .. W - 1 and show bit i at bit 0.
    dda_serial #(.IncWidth(IncWidth), .KWidth(KWidth)) u_dry_run (
      .clk_i, .rst_ni,
      .load_i(start), .line_i(1'b0), .k_i(k), .x_bit_i(shift_o && i_i[0]),
      .y_bit_i(shift_o && j_i[0]), .cnt_x_bit_i(shift_o && dx_i[0]),
      .cnt_y_bit_i(shift_o && dy_i[0]), .bit_o(dry_bit),
      .grow_x_i(grow_x), .grow_y_i(grow_y), .dir_x_i(1'b0), .dir_y_i(1'b0),
      .strobe_i(running_q), .mute_i(1'b0), .iterate_o(dry_iterate),
      .carry_x_o(dry_carry_x), .carry_y_o(dry_carry_y), .step_x_o(dry_step_x),
      .dir_x_o(dry_dir_x), .step_y_o(dry_step_y), .dir_y_o(dry_dir_y),
      .words_o(dry_words), .done_o(dry_done)
    );
  end else begin : g_parallel_dry_run
    // The dry run emits no pulses and has no direction.
    /* verilator lint_off UNUSEDSIGNAL */
    logic dry_carry_x, dry_carry_y, dry_step_x, dry_step_y, dry_dir_x, dry_dir_y;
    /* verilator lint_on UNUSEDSIGNAL */
    dda_circle #(.IncWidth(IncWidth), .KWidth(KWidth)) u_dry_run (
      .clk_i, .rst_ni,
      .load_i(start), .line_i(1'b0), .k_i(k), .x_i(i_i), .y_i(j_i), .cnt_x_i(dx_i),
      .cnt_y_i(dy_i), .grow_x_i(grow_x), .grow_y_i(grow_y), .dir_x_i(1'b0), .dir_y_i(1'b0),
      .strobe_i(running_q),
      .carry_x_o(dry_carry_x), .carry_y_o(dry_carry_y), .step_x_o(dry_step_x),
      .dir_x_o(dry_dir_x), .step_y_o(dry_step_y), .dir_y_o(dry_dir_y),
      .done_o(dry_done)
    );
    // One iteration at every running edge until done (done_o is stable in the clock).
    assign dry_iterate = !dry_done;
  end

  arc_radius_check #(.IncWidth(IncWidth)) u_radius (
    .clk_i, .rst_ni, .start_i(start),
    .x0_bit_i(i_i[0]), .y0_bit_i(j_i[0]), .dx_bit_i(dx_i[0]), .dy_bit_i(dy_i[0]),
    .add_x_i(add_x), .add_y_i(add_y), .shift_o(check_shift),
    .done_o(check_done), .ok_o(check_ok)
  );

  always_comb begin
    done_o     = 1'b0;
    err_o      = 1'b0;
    err_code_o = interp_pkg::ErrArcEndpointOffCircle;
    if (start && geo_err) begin
      done_o     = 1'b1;
      err_o      = 1'b1;
      err_code_o = geo_code;
    end else if (running_q && check_done && (!check_ok || dry_done)) begin
      done_o = 1'b1;
      err_o  = !check_ok;
    end

    running_d = running_q;
    iterate_o = 1'b0;
    if (start) begin
      running_d = !geo_err;
    end else if (!run_i || done_o) begin
      running_d = 1'b0;
    end else begin
      iterate_o = dry_iterate;
    end
  end

  always_ff @(posedge clk_i) begin
    if (!rst_ni) begin
      running_q <= 1'b0;
    end else begin
      running_q <= running_d;
    end
  end

  // The words turn only while the arc is prepared: after a geometric error at the start edge
  // the check runs on unseen (the decoder has stopped).
  assign shift_o  = geo_shift || (check_shift && running_q);
  assign k_o      = k;
  assign grow_x_o = grow_x;
  assign grow_y_o = grow_y;

endmodule
