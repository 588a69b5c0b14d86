// Tape decoder: 8-bit frames (ISO 840 even parity) -> word-address blocks (ISO 6983).
//
// What: takes one frame per clock over valid/ready and assembles one motion block, which it
// holds (frame_ready_o low) until the block buffer takes it. Three parts, in the order of
// docs/interpolator.md section 3:
//   - frame input (tape_frame_input.sv, 3.1): handshake, input register, parity, offset;
//   - word parser (tape_word_parser.sv, 3.2): the words N G M X Y I J F, strict syntax;
//   - block assembly with error capture (this module, 3.3 and 3.4): the decoder's state,
//     the words' meaning (G and F are modal), the block's end, the handoff, and the first
//     error, with its code, the bad block's N (or the previous one) and the frame's offset.
// A block with an M word that acts (M00, M01, M03, M05: tape_codes.def) and no motion word
// is a still block, handed over as a G00 of length 0 (its S the rapid step, N = 1), so the
// player plays it as any block and acts at its start and end; the modal motion stays.
// A motion block is prepared before it is held: the feed generator's step S is summed here
// serially, on one register and one adder: a line's S = F << k is F added once, then
// doubled (S + S) k times; an arc block (G02/G03) is checked and dry-run by arc_prepare.sv
// (3.5), and F is added at each of its circle DDA's N iterations: S = F * N. The error is
// only reported by interp_top once every good block has played.
// Golden twin: GoldenTapeDecoder (sc_model/golden/tape_decoder.h), whose sections "Frame
// input", "Word parser" and "Block assembly and error capture" follow these three parts
// decision by decision.
//
// Timing: a frame taken at edge e is processed at edge e+1 (tape_frame_input.sv). The LF of
// a motion block puts the decoder in PREPARE: a line for k + 2 clocks (S = 0 at the LF,
// F at the next edge, doubled at the k edges after, HOLD at the one after), an arc until
// arc_prepare is done (max(N, C) clocks, or W + 1 + max(2PN, C) with BitSerial; C =
// (5W + 4)(2W + 4) for the radius check), then HOLD or ERROR; the block buffer takes a held
// block at the first edge where it is empty (blk_ready_i). With BitSerial a digit
// processed at edge e holds the next frame until edge e + NumWidth + 1 (its x10 + d pass;
// a value over the word's limit is an error at edge e + NumWidth).
// tape_end_i (registered) with no frame waiting in LEADER/BODY/COMMENT is a truncated tape.
// All outputs are functions of registers.
module tape_decoder #(
  // Increment register width W: |X|, |Y|, |I|, |J| <= 2^IncWidth - 1 BLU.
  parameter int IncWidth       = 16,
  // Fraction digits of X, Y, I, J on tape (exactly this many).
  parameter int FracDigits     = 3,
  // F register width and fraction digits.
  parameter int FeedWidth      = 32,
  parameter int FeedFracDigits = 3,
  // N register width.
  parameter int SeqWidth       = 20,
  // Frame offset counter width (error reports).
  parameter int OffsetWidth    = 32,
  // The feed step S: its low StepWidth bits and whether it reached 2^StepWidth
  // (interp_top.sv: any S that large saturates the block).
  parameter int StepWidth      = FeedWidth + IncWidth + 1,
  // rapid_step_i's width (interp_top's feed modulus width).
  parameter int ModulusWidth   = 48,
  // The per-block arithmetic in parallel (0) or bit-serial (1, the board's choice): the
  // arc's dry run (arc_prepare.sv) and each digit's x10 + d (tape_word_parser.sv).
  parameter bit BitSerial      = 1'b0,
  // Circle mode built in (interp_top's CircleMode); without it a G02/G03 word is an error
  // (ErrNoCircleMode), I and J are read but not kept, and there is no arc preparation.
  parameter bit CircleMode     = 1'b1,
  // The feed ramp is built (interp_top's Accel): only it reads the block's N, so without it
  // N is a constant 0 and its count folds away.
  parameter bit Accel          = 1'b1,
  // M00, M01, M03 and M05 are played (interp_top's MiscFunctions); without them each is an
  // unsupported code (error 6).
  parameter bit MiscFunctions  = 1'b1
) (
  // The ports are declared below, after block_t (`INTERP_BLOCK_T), which the block's
  // port has as its type and which needs the parameters above.
  clk_i, rst_ni, rapid_step_i, frame_i, frame_valid_i, tape_end_i, frame_ready_o,
  blk_valid_o, blk_ready_i, blk_o,
  end_o, tape_ended_o, err_o, err_code_o, err_block_o, err_offset_o
);

  localparam int KWidth = $clog2(IncWidth + 1);
  localparam int IterWidth = Accel ? IncWidth + 1 : 1;  // the block's N (block_record.def)
  `INTERP_BLOCK_T

  input  logic                   clk_i;
  input  logic                   rst_ni;
  // A rapid traverse's S (interp_top's static rapid_step_i).
  input  logic [ModulusWidth-1:0] rapid_step_i;
  // Tape reader.
  input  logic [7:0]             frame_i;
  input  logic                   frame_valid_i;
  input  logic                   tape_end_i;
  output logic                   frame_ready_o;
  // The decoded motion block, valid while held; taken at an edge with blk_ready_i. Its S:
  // F << k for a line, F * N for an arc (N < 2^(W+1)), modulo 2^StepWidth, and whether
  // S >= 2^StepWidth (the block is saturated).
  output logic                   blk_valid_o;
  input  logic                   blk_ready_i;
  output block_t                 blk_o;
  // End of program decoded and its last block handed over; trailing frames are checked.
  output logic                   end_o;
  // The reader has delivered every frame (tape_end_i, registered).
  output logic                   tape_ended_o;
  // An error is held (the decoder has stopped).
  output logic                   err_o;
  output logic [interp_pkg::ErrCodeWidth-1:0] err_code_o;
  output logic [SeqWidth-1:0]    err_block_o;
  output logic [OffsetWidth-1:0] err_offset_o;

  // The word parser's value width: the widest register a word fills.
  localparam int NumWidth0 = IncWidth > FeedWidth ? IncWidth : FeedWidth;
  localparam int NumWidth1 = NumWidth0 > SeqWidth ? NumWidth0 : SeqWidth;
  localparam int NumWidth  = NumWidth1 > 7 ? NumWidth1 : 7;

  typedef enum logic [2:0] {
    StLeader  = 3'd0,  // before '%': frames skipped
    StBody    = 3'd1,  // reading blocks
    StComment = 3'd2,  // inside ( ... )
    StHold    = 3'd3,  // a decoded motion block waits for the block buffer
    StEnd     = 3'd4,  // after the end block: only % NUL CR LF space
    StError   = 3'd5,  // stopped on an error
    StPrepare = 3'd6   // a motion block's S is summed (and an arc checked, arc_prepare)
  } state_e;

  state_e state_q, state_d;

  // Frame input: the frame processed at this edge (take), its character, parity and offset.
  logic                   take, parity_err, waiting, tape_end_q;
  logic [6:0]             ch;
  logic [OffsetWidth-1:0] offset;

  // Word parser: its error, and the word a delimiter ends or starts.
  logic                   body_char;  // a body character reaches the parser at this edge
  logic                   word_err, delimiter, word_end, word_neg, word_start, word_err_at_word;
  logic [interp_pkg::ErrCodeWidth-1:0] word_err_code;
  logic [OffsetWidth-1:0] word_offset;
  logic [6:0]             word_letter;
  logic [NumWidth-1:0]    word_value;
  // BitSerial: a digit's pass runs (no frame is processed), and its limit check's verdict.
  logic                   word_busy, word_busy_next, word_value_err;

  // Block assembly. n_q is the last N read (never cleared: a block without N carries the
  // previous one); motion_q (interp_pkg::motion_e) and feed_q are modal (G01 and "no feed"
  // after reset).
  logic [SeqWidth-1:0]  n_q, n_d;
  logic [1:0]           motion_q, motion_d;
  logic [FeedWidth-1:0] feed_q, feed_d;
  // X, Y, I, J (sign and magnitude): each loads the word parser's number when its word is
  // committed (load_dx ...) and clears when the block ends, so a bit is a flip-flop with its
  // enable and synchronous reset; the magnitudes also turn one place per clock while an
  // arc's preparation reads them bit by bit (arc_shift, arc_prepare.sv).
  logic [IncWidth-1:0]  dx_q, dy_q, i_q, j_q;
  logic                 dx_neg_q, dy_neg_q, i_neg_q, j_neg_q;
  logic                 load_dx, load_dy, load_i, load_j;
  // k of the held block: for a line the bit length of (|dx| | |dy|) = bit length of
  // max(|dx|, |dy|) (the line DDA runs 2^k iterations), computed at its first PREPARE edge;
  // for an arc the circle DDA's k and the growth of |x|, |y|, from arc_prepare's geometry
  // when the arc is ready. So the player has nothing to compute at the load.
  logic [KWidth-1:0]    k_q, k_d;
  // step_q: the block's feed step S, summed in PREPARE on one adder, one addition per
  // clock (no multiplier or barrel shifter): S = 0 at the LF, then S + F for a line's first
  // clock and an arc's every dry-run iteration, S + S for a line's k doublings. Its low
  // StepWidth bits; step_over_q: it reached 2^StepWidth (a carry out, or an F that does not
  // fit), which saturates the block whatever the rest (a flag instead of all ones in S:
  // the adder's sum goes to the register as it is). feed_in_q: a line's F is still to add.
  // shifts_q: a line's doublings still to do.
  logic [StepWidth-1:0] step_q, step_d, step_addend, step_sum;
  logic                 step_over_q, step_over_d, feed_in_q, feed_in_d, step_carry, feed_over,
                        step_add, rapid;
  logic [KWidth-1:0]    shifts_q, shifts_d;
  // iter_q: the block's N, for the feed ramp: 2^k for a line (set with k), an arc's dry-run
  // iterations counted.
  logic [IncWidth:0]    iter_q, iter_d;
  logic                 grow_x_q, grow_x_d, grow_y_q, grow_y_d;
  // Per-block flags: an N word was read; any word was read; the block moves (X/Y/I/J or
  // a motion G); the block ends the program (M02/M30); its M word acts: M00 (stop_q), M01,
  // M03, M05 (the block record's fields of the same names). m_seen: an M word was read.
  logic n_seen_q, n_seen_d, any_word_q, any_word_d;
  logic motion_blk_q, motion_blk_d, end_blk_q, end_blk_d;
  logic stop_q, stop_d, optional_stop_q, optional_stop_d, tool_on_q, tool_on_d;
  logic tool_off_q, tool_off_d, m_seen, action_d, still;
  // (Each use is gated by MiscFunctions, so that without them the logic is that of a decoder
  // that never had them: synthesis cannot see that these flip-flops stay 0.)
  assign m_seen = end_blk_q | (MiscFunctions & (stop_q | optional_stop_q | tool_on_q | tool_off_q));
  // The block held or prepared is a still block: an M word without motion words.
  assign still  = MiscFunctions && !motion_blk_q;

  // Error capture: the first error found (valid in StError). Its block is n_q: n_d at the
  // error's edge, and no N is committed in StError; its offset is the frame input's
  // counter, which the error's edge sets to it (fail_back, fail_word) and which no frame
  // moves after it.
  logic [interp_pkg::ErrCodeWidth-1:0] err_code_q, err_code_d;

  // Combinational helpers.
  logic                   update;       // the block assembly's registers change at this edge
  state_e                 state_next;   // the state after this edge
  logic                   tape_cut;     // truncated tape found at this edge
  logic                   fail;         // an error is found at this edge
  logic [interp_pkg::ErrCodeWidth-1:0] fail_code;
  // The error's offset: the frame processed at this edge (or, with none, the next one);
  // fail_back: the last frame processed; fail_word: the word's letter (word_offset).
  logic                   fail_back, fail_word;
  logic                   word_ok;      // the word ended by this frame was committed
  logic [interp_pkg::ErrCodeWidth-1:0] word_refusal; // else why not: an unsupported code, or an arc
                                        // without circle mode
  logic                   word_commit;  // a word ends at this edge (its register loads)
  logic                   clear_block;  // the block's per-block registers clear at this edge
  // The block being prepared (StPrepare); for an arc, arc_prepare's result is in the clock
  // with arc_done, and arc_iterate marks its dry run's iterations. preparing and in_arc are
  // their own signals because Icarus 11 mistypes an enum literal used in a port connection.
  logic                   preparing, in_arc, arc_done, arc_err, arc_grow_x, arc_grow_y;
  logic                   arc_iterate, arc_shift;
  logic [interp_pkg::ErrCodeWidth-1:0] arc_code;
  logic [KWidth-1:0]      arc_k;

  // Bit length of a value (position of its highest 1 plus one; 0 for 0).
  function automatic logic [KWidth-1:0] bit_length(input logic [IncWidth-1:0] value);
    bit_length = '0;
    for (int b = 0; b < IncWidth; b++) begin
      if (value[b]) bit_length = KWidth'(b + 1);
    end
  endfunction

  tape_frame_input #(.OffsetWidth(OffsetWidth)) u_frame (
    .clk_i, .rst_ni, .frame_i, .frame_valid_i, .tape_end_i, .frame_ready_o,
    .accept_i(state_q != StHold && !preparing && state_q != StError && !word_busy),
    .error_next_i(state_next == StError),
    .busy_next_i(state_next == StHold || state_next == StPrepare || word_busy_next),
    .err_i(update && fail), .err_back_i(fail_back), .err_word_i(fail_word),
    .word_offset_i(word_offset),
    .take_o(take), .char_o(ch), .parity_err_o(parity_err), .offset_o(offset),
    .waiting_o(waiting), .tape_ended_o(tape_end_q)
  );

  assign body_char = take && !parity_err && state_q == StBody;

  tape_word_parser #(
    .IncWidth(IncWidth), .FracDigits(FracDigits), .FeedWidth(FeedWidth),
    .FeedFracDigits(FeedFracDigits), .SeqWidth(SeqWidth), .OffsetWidth(OffsetWidth),
    .NumWidth(NumWidth), .BitSerial(BitSerial)
  ) u_word (
    .clk_i, .rst_ni, .char_valid_i(body_char), .char_i(ch), .offset_i(offset),
    .err_o(word_err), .err_code_o(word_err_code), .err_at_word_o(word_err_at_word),
    .delimiter_o(delimiter), .word_end_o(word_end), .word_letter_o(word_letter),
    .word_value_o(word_value), .word_neg_o(word_neg), .word_offset_o(word_offset),
    .word_start_o(word_start), .busy_o(word_busy), .busy_next_o(word_busy_next),
    .value_err_o(word_value_err)
  );

  assign preparing = state_q == StPrepare;
  assign in_arc    = CircleMode && preparing && !still && interp_pkg::motion_is_arc(motion_q);
  // The reader has delivered every frame, none waits, and the program has not ended.
  assign tape_cut = tape_end_q && !waiting &&
                    (state_q == StLeader || state_q == StBody || state_q == StComment);
  assign update = take || preparing || state_q == StHold || tape_cut || word_busy;
  assign state_next = update ? state_d : state_q;

  always_comb begin
    // Clocks without an update (most clocks: the reader is slow) evaluate nothing here:
    // the registers keep their values (the always_ff's enable), so the next-state values
    // are don't-care ('x): the verilated model skips them (fast) and synthesis folds the 'x
    // away (no gate per next-state bit).
    {state_d, n_d, motion_d, feed_d,
     n_seen_d, any_word_d, motion_blk_d, end_blk_d, stop_d, optional_stop_d, tool_on_d,
     tool_off_d, action_d, err_code_d, k_d,
     step_d, shifts_d, grow_x_d, grow_y_d, fail, fail_code, fail_back, fail_word, word_ok,
     word_refusal,
     step_over_d, feed_in_d, step_addend, step_carry, step_sum, feed_over,
     step_add, rapid, iter_d} = 'x;
    word_commit = 1'b0;
    clear_block = 1'b0;
    if (update) begin
      state_d       = state_q;
      n_d           = n_q;
      motion_d      = motion_q;
      feed_d        = feed_q;
      n_seen_d      = n_seen_q;
      any_word_d    = any_word_q;
      motion_blk_d  = motion_blk_q;
      end_blk_d     = end_blk_q;
      stop_d        = stop_q;
      optional_stop_d = optional_stop_q;
      tool_on_d     = tool_on_q;
      tool_off_d    = tool_off_q;
      err_code_d    = err_code_q;
      k_d           = k_q;
      step_d        = step_q;
      step_over_d   = step_over_q;
      feed_in_d     = feed_in_q;
      shifts_d      = shifts_q;
      iter_d        = iter_q;
      grow_x_d      = grow_x_q;
      grow_y_d      = grow_y_q;
      fail          = 1'b0;
      fail_code     = interp_pkg::ErrParity;
      fail_back     = 1'b0;
      fail_word     = 1'b0;
      word_ok       = 1'b1;
      word_refusal  = interp_pkg::ErrUnsupportedCode;

      if (take) begin
        if (parity_err) begin
          fail = 1'b1;
        end else begin
          unique case (state_q)
            StLeader:  if (ch == interp_pkg::ChPercent) state_d = StBody;
            StComment: if (ch == interp_pkg::ChClose) state_d = StBody;
            StEnd: begin
              if (!(ch == interp_pkg::ChPercent || ch == interp_pkg::ChNul ||
                    ch == interp_pkg::ChCr || ch == interp_pkg::ChLf ||
                    ch == interp_pkg::ChSpace)) begin
                fail = 1'b1;
                fail_code = interp_pkg::ErrBlockAfterEnd;
              end
            end
            StBody: begin
              if (word_err) begin
                fail = 1'b1;
                fail_code = word_err_code;
                fail_word = word_err_at_word;
              end else if (delimiter) begin
                // The word this character ends is committed first.
                if (word_end) begin
                  word_commit = 1'b1;
                  unique case (word_letter)
                    interp_pkg::ChN: n_d = word_value[SeqWidth-1:0];
                    // A G or M code is <= 99 (the word parser's limit for them): its
                    // low 7 bits are all of it, so only those are compared.
                    interp_pkg::ChG: begin
                      if (interp_pkg::g_motion(word_value[6:0])) begin
                        // The G number is the motion code.
                        motion_d = word_value[interp_pkg::MotionWidth-1:0];
                        motion_blk_d = 1'b1;
                        // Without circle mode an arc's G word is refused where it stands.
                        if (!CircleMode && interp_pkg::motion_is_arc(motion_d)) begin
                          word_ok = 1'b0;
                          word_refusal = interp_pkg::ErrNoCircleMode;
                        end
                      end else if (!interp_pkg::g_setting(word_value[6:0])) begin
                        word_ok = 1'b0;
                      end
                    end
                    // One M word per block: each acts at its own point of the block.
                    interp_pkg::ChM: begin
                      if (m_seen) word_ok = 1'b0;
                      else if (interp_pkg::m_end(word_value[6:0])) end_blk_d = 1'b1;
                      else if (!MiscFunctions) word_ok = 1'b0;
                      else if (interp_pkg::m_stop(word_value[6:0])) stop_d = 1'b1;
                      else if (interp_pkg::m_optional_stop(word_value[6:0]))
                        optional_stop_d = 1'b1;
                      else if (interp_pkg::m_tool_on(word_value[6:0])) tool_on_d = 1'b1;
                      else if (interp_pkg::m_tool_off(word_value[6:0])) tool_off_d = 1'b1;
                      else word_ok = 1'b0;
                    end
                    // X, Y, I, J load their registers (load_dx ... below).
                    interp_pkg::ChX, interp_pkg::ChY, interp_pkg::ChI, interp_pkg::ChJ:
                      motion_blk_d = 1'b1;
                    default: feed_d = word_value[FeedWidth-1:0];  // F
                  endcase
                  if (!word_ok) begin
                    fail = 1'b1;
                    fail_code = word_refusal;
                    fail_word = 1'b1;
                  end
                end
                // Then the character itself.
                if (word_ok) begin
                  if (word_start) begin
                    if (ch == interp_pkg::ChN && n_seen_q) begin
                      fail = 1'b1;
                      // a second N: the LF is missing
                      fail_code = interp_pkg::ErrMissingEndOfBlock;
                    end else begin
                      if (ch == interp_pkg::ChN) n_seen_d = 1'b1;
                      any_word_d = 1'b1;
                    end
                  end else if (ch == interp_pkg::ChLf) begin
                    action_d = MiscFunctions & (stop_d | optional_stop_d | tool_on_d | tool_off_d);
                    if (motion_blk_d || action_d) begin
                      // G00 plays at the rapid rate: it needs no F; nor does a still block.
                      if (motion_blk_d && feed_d == '0 &&
                          motion_d != interp_pkg::MotionRapid) begin
                        fail = 1'b1;
                        fail_code = interp_pkg::ErrMissingFeed;
                      end else begin
                        // Prepared first (the block is cleared at the handoff): S
                        // starts at 0; a line adds F, then doubles it k times (k from
                        // its first PREPARE clock on, when X and Y are in their registers).
                        state_d     = StPrepare;
                        step_d      = '0;
                        step_over_d = 1'b0;
                        iter_d      = '0;
                        feed_in_d   = !interp_pkg::motion_is_arc(motion_d);
                      end
                    end else begin
                      if (end_blk_d) state_d = StEnd;
                      clear_block = 1'b1;
                    end
                  end else if (ch == interp_pkg::ChOpen) begin
                    state_d = StComment;
                  end else if (ch == interp_pkg::ChPercent) begin
                    fail = 1'b1;
                    fail_code = any_word_q ? interp_pkg::ErrMissingEndOfBlock
                                           : interp_pkg::ErrTruncatedTape;
                  end else begin
                    fail = 1'b1;
                    fail_code = interp_pkg::ErrUnknownCharacter;
                  end
                end
              end
            end
            default: ;  // StHold, StPrepare, StError: no frame is processed
          endcase
        end
      end else if (word_busy) begin
        // BitSerial: a digit's pass; at its last edge, over the word's limit or not.
        if (word_value_err) begin
          fail = 1'b1;
          fail_code = interp_pkg::ErrValueTooWide;
          fail_back = 1'b1;  // the digit, the last frame processed
        end
      end else if (preparing) begin
        // The one adder: S + F (a line's first clock, an arc's iterations), S + the rapid
        // step (a rapid traverse's first clock) or S + S (a line's doublings). An addend
        // wider than S over-runs S by itself.
        rapid       = motion_q == interp_pkg::MotionRapid || still;
        step_addend = !in_arc && !feed_in_q ? step_q
                    : rapid ? StepWidth'(rapid_step_i) : StepWidth'(feed_q);
        feed_over   = !in_arc && !feed_in_q ? 1'b0
                    : rapid ? ((ModulusWidth + StepWidth)'(rapid_step_i) >> StepWidth) != '0
                            : ((FeedWidth + StepWidth)'(feed_q) >> StepWidth) != '0;
        {step_carry, step_sum} = {1'b0, step_q} + {1'b0, step_addend};
        // A line adds F at its first clock, then doubles once per clock (S = F << k); a
        // rapid traverse adds its step once (its k is the line's, its S the same whatever
        // its length); an arc adds F once per dry-run iteration (S = F * N).
        step_add = in_arc ? arc_iterate : feed_in_q || shifts_q != '0;
        if (step_add) begin
          step_d      = step_sum;
          step_over_d = step_over_q || step_carry || feed_over;
        end
        if (in_arc && arc_iterate) iter_d = iter_q + 1'b1;
        if (!in_arc) begin
          feed_in_d = 1'b0;
          if (!step_add) begin
            state_d = StHold;
          end else if (!feed_in_q) begin
            shifts_d = shifts_q - 1'b1;
          end else begin
            k_d      = bit_length(dx_q | dy_q);
            shifts_d = rapid ? '0 : k_d;
            iter_d   = (IncWidth + 1)'(1) << k_d;
          end
        end else if (arc_done) begin
          if (arc_err) begin
            fail = 1'b1;
            fail_code = arc_code;
            fail_back = 1'b1;  // the block's LF, the last frame processed
          end else begin
            state_d  = StHold;
            k_d      = arc_k;
            grow_x_d = arc_grow_x;
            grow_y_d = arc_grow_y;
          end
        end
      end else if (state_q == StHold) begin
        if (blk_ready_i) begin
          if (end_blk_q) state_d = StEnd;
          else state_d = StBody;
          clear_block = 1'b1;
        end
      end else if (tape_cut) begin
        fail = 1'b1;
        fail_code = interp_pkg::ErrTruncatedTape;  // at the offset of the frame that never came
      end

      // A block ends (an LF without motion, or the handoff): its per-block registers clear
      // (X, Y, I, J in their own always_ff below).
      if (clear_block) begin
        n_seen_d = 1'b0;  any_word_d = 1'b0;  motion_blk_d = 1'b0;  end_blk_d = 1'b0;
        stop_d = 1'b0;  optional_stop_d = 1'b0;  tool_on_d = 1'b0;  tool_off_d = 1'b0;
      end

      if (fail) begin
        state_d      = StError;
        err_code_d   = fail_code;  // its block: n_d, which includes an N committed by this frame
      end
    end
  end

  assign load_dx = word_commit && word_letter == interp_pkg::ChX;
  assign load_dy = word_commit && word_letter == interp_pkg::ChY;
  // Without circle mode I and J are read (the syntax is the same) but not kept.
  assign load_i  = CircleMode && word_commit && word_letter == interp_pkg::ChI;
  assign load_j  = CircleMode && word_commit && word_letter == interp_pkg::ChJ;
  always_ff @(posedge clk_i) begin
    if (!rst_ni || clear_block) begin
      {dx_neg_q, dx_q, dy_neg_q, dy_q, i_neg_q, i_q, j_neg_q, j_q} <= '0;
    end else if (arc_shift) begin
      // An arc's check and dry run read the magnitudes one bit per clock (arc_prepare.sv).
      dx_q <= {dx_q[0], dx_q[IncWidth-1:1]};
      dy_q <= {dy_q[0], dy_q[IncWidth-1:1]};
      i_q  <= {i_q[0], i_q[IncWidth-1:1]};
      j_q  <= {j_q[0], j_q[IncWidth-1:1]};
    end else begin
      if (load_dx) {dx_neg_q, dx_q} <= {word_neg, word_value[IncWidth-1:0]};
      if (load_dy) {dy_neg_q, dy_q} <= {word_neg, word_value[IncWidth-1:0]};
      if (load_i)  {i_neg_q, i_q}   <= {word_neg, word_value[IncWidth-1:0]};
      if (load_j)  {j_neg_q, j_q}   <= {word_neg, word_value[IncWidth-1:0]};
    end
  end

  // Arc blocks: the checks and the dry run that counts the circle DDA's iterations N (the
  // decoder adds F at each, above). Without circle mode no arc is ever prepared.
  if (CircleMode) begin : g_arcs
    arc_prepare #(.IncWidth(IncWidth), .KWidth(KWidth), .BitSerial(BitSerial)) u_arc (
      .clk_i, .rst_ni, .run_i(in_arc),
      .dx_i(dx_q), .dx_neg_i(dx_neg_q), .dy_i(dy_q), .dy_neg_i(dy_neg_q),
      .i_i(i_q), .i_neg_i(i_neg_q), .j_i(j_q), .j_neg_i(j_neg_q),
      .ccw_i(motion_q == interp_pkg::MotionArcCcw),
      .done_o(arc_done), .err_o(arc_err), .err_code_o(arc_code), .iterate_o(arc_iterate),
      .shift_o(arc_shift),
      .k_o(arc_k), .grow_x_o(arc_grow_x), .grow_y_o(arc_grow_y)
    );
  end else begin : g_lines
    /* verilator lint_off UNUSEDSIGNAL */
    logic unused_signs;  // an arc's I and J are never read
    /* verilator lint_on UNUSEDSIGNAL */
    assign unused_signs = i_neg_q ^ j_neg_q;
    assign {arc_done, arc_err, arc_iterate, arc_shift, arc_grow_x, arc_grow_y} = '0;
    assign arc_code = interp_pkg::ErrNone;
    assign arc_k = '0;
  end

  // The registers change only when a frame is processed, an arc is prepared, a held block
  // is handed over or the tape has ended (update).
  always_ff @(posedge clk_i) begin
    if (!rst_ni) begin
      state_q       <= StLeader;
      n_q           <= '0;
      motion_q      <= interp_pkg::MotionLine;
      feed_q        <= '0;
      k_q           <= '0;
      step_q        <= '0;
      step_over_q   <= 1'b0;
      feed_in_q     <= 1'b0;
      shifts_q      <= '0;
      iter_q        <= '0;
      grow_x_q      <= 1'b0;
      grow_y_q      <= 1'b0;
      n_seen_q      <= 1'b0;
      any_word_q    <= 1'b0;
      motion_blk_q  <= 1'b0;
      end_blk_q     <= 1'b0;
      stop_q        <= 1'b0;
      optional_stop_q <= 1'b0;
      tool_on_q     <= 1'b0;
      tool_off_q    <= 1'b0;
      err_code_q    <= '0;
    end else if (update) begin
      state_q       <= state_d;
      n_q           <= n_d;
      motion_q      <= motion_d;
      feed_q        <= feed_d;
      k_q           <= k_d;
      step_q        <= step_d;
      step_over_q   <= step_over_d;
      feed_in_q     <= feed_in_d;
      shifts_q      <= shifts_d;
      iter_q        <= iter_d;
      grow_x_q      <= grow_x_d;
      grow_y_q      <= grow_y_d;
      n_seen_q      <= n_seen_d;
      any_word_q    <= any_word_d;
      motion_blk_q  <= motion_blk_d;
      end_blk_q     <= end_blk_d;
      stop_q        <= stop_d;
      optional_stop_q <= optional_stop_d;
      tool_on_q     <= tool_on_d;
      tool_off_q    <= tool_off_d;
      err_code_q    <= err_code_d;
    end
  end

  assign blk_o.n         = n_q;
  assign blk_o.motion    = still ? interp_pkg::MotionRapid : motion_q;  // still: G00
  assign blk_o.stop      = MiscFunctions & stop_q;
  assign blk_o.optional_stop = MiscFunctions & optional_stop_q;
  assign blk_o.tool_on   = MiscFunctions & tool_on_q;
  assign blk_o.tool_off  = MiscFunctions & tool_off_q;
  assign blk_o.dx        = dx_q;
  assign blk_o.dx_neg    = dx_neg_q;
  assign blk_o.dy        = dy_q;
  assign blk_o.dy_neg    = dy_neg_q;
  assign blk_o.i         = i_q;
  assign blk_o.j         = j_q;
  assign blk_o.step      = step_q;
  assign blk_o.step_over = step_over_q;
  assign blk_o.k         = k_q;
  assign blk_o.grow_x    = grow_x_q;
  assign blk_o.grow_y    = grow_y_q;
  assign blk_o.iterations = Accel ? IterWidth'(iter_q) : '0;
  assign blk_valid_o     = state_q == StHold;
  assign end_o         = state_q == StEnd;
  assign tape_ended_o  = tape_end_q;
  assign err_o         = state_q == StError;
  assign err_code_o    = err_code_q;
  assign err_block_o   = n_q;
  assign err_offset_o  = offset;

endmodule
