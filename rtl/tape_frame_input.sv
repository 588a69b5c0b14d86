// Tape decoder, frame input (docs/interpolator.md 3.1): the reader handshake, the input
// register, the ISO 840 parity check and the frame offset (after an error: its offset).
//
// What: a frame taken at edge e (frame_valid_i & frame_ready_o) lands in the input register
// and is processed at edge e+1 (take_o), while the next frame may be taken. Its 7 character
// bits, its parity (an odd count of ones in all 8 bits is a parity error) and its offset on
// the tape go to the word parser and the block assembly of tape_decoder.sv. frame_ready_o
// is a register: low while the register is full and the decoder will not process it at the
// next edge (it holds a block or prepares an arc), and after an error. The frame counter
// is also the error's offset: at the edge where the decoder finds an error (err_i) it does
// not count the frame taken, steps back to the last frame processed (err_back_i) or takes
// the offset of the word's letter (err_word_i, word_offset_i), and no frame is taken after
// it, so offset_o is the error's offset from then on (one counter, no register of its own
// and no subtractor for it).
// Idea: registering the reader's signals first means no logic of the decoder depends on an
// input combinationally (a simulator re-evaluates input-dependent logic on every input
// change, and the board's reader is asynchronous to nothing but this register).
// Golden twin: the section "Frame input" of GoldenTapeDecoder
// (sc_model/golden/tape_decoder.cpp: edge(), process_frame()).
module tape_frame_input #(
  // Frame offset counter width (error reports).
  parameter int OffsetWidth = 32
) (
  input  logic                   clk_i,
  input  logic                   rst_ni,
  // Tape reader.
  input  logic [7:0]             frame_i,
  input  logic                   frame_valid_i,
  input  logic                   tape_end_i,
  output logic                   frame_ready_o,
  // The decoder processes a frame at this edge if one waits (it reads, skips a leader or a
  // comment, or checks the trailer).
  input  logic                   accept_i,
  // The decoder's state after this edge: stopped on an error; holding a block or preparing
  // an arc (it will not process a frame at the next edge).
  input  logic                   error_next_i,
  input  logic                   busy_next_i,
  // An error is found at this edge; its offset is the last frame processed (err_back_i) or
  // the word's letter (err_word_i: word_offset_i), else the frame taken now or, with none
  // taken, the next one.
  input  logic                   err_i,
  input  logic                   err_back_i,
  input  logic                   err_word_i,
  input  logic [OffsetWidth-1:0] word_offset_i,
  // The frame processed at this edge (take_o): character, parity error, offset on the tape
  // (after an error: the error's offset).
  output logic                   take_o,
  output logic [6:0]             char_o,
  output logic                   parity_err_o,
  output logic [OffsetWidth-1:0] offset_o,
  // A frame waits in the register; the reader has delivered every frame (registered).
  output logic                   waiting_o,
  output logic                   tape_ended_o
);

  logic [7:0] in_frame_q, in_frame_d;
  logic       in_valid_q, in_valid_d, tape_end_q, ready_q, ready_d;
  // Offset of the next frame: the offset reported for an error in the frame being taken;
  // after an error, the error's offset.
  logic [OffsetWidth-1:0] frame_count_q;

  assign take_o = in_valid_q && accept_i;

  always_comb begin
    in_frame_d = in_frame_q;
    in_valid_d = in_valid_q && !take_o;
    if (frame_valid_i && ready_q) begin
      in_frame_d = frame_i;
      in_valid_d = 1'b1;
    end
    ready_d = !error_next_i && !(busy_next_i && in_valid_d);
  end

  always_ff @(posedge clk_i) begin
    if (!rst_ni) begin
      in_frame_q    <= '0;
      in_valid_q    <= 1'b0;
      tape_end_q    <= 1'b0;
      ready_q       <= 1'b1;
      frame_count_q <= '0;
    end else begin
      in_frame_q <= in_frame_d;
      in_valid_q <= in_valid_d;
      tape_end_q <= tape_end_i;
      ready_q    <= ready_d;
      // One adder: + 1 for a frame taken, - 1 back to the last frame processed.
      if (err_i && err_word_i) frame_count_q <= word_offset_i;
      else if (err_i ? err_back_i : take_o)
        frame_count_q <= frame_count_q + {{(OffsetWidth - 1){err_i}}, 1'b1};
    end
  end

  assign frame_ready_o = ready_q;
  assign char_o        = in_frame_q[6:0];
  assign parity_err_o  = ^in_frame_q;  // even parity: ISO 840
  assign offset_o      = frame_count_q;
  assign waiting_o     = in_valid_q;
  assign tape_ended_o  = tape_end_q;

endmodule
