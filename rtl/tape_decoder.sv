// Tape decoder: 8-bit frames (ISO 840 even parity) -> word-address blocks (ISO 6983).
//
// What: takes one frame per clock over valid/ready, checks its parity, parses the words
// N G M X Y I J F (strict number syntax, docs/interpolator.md section 3), assembles one
// motion block and holds it (frame_ready_o low) until the block buffer takes it. G and F
// are modal. An arc block (G02/G03) is first checked and dry-run by arc_prepare.sv, which
// gives its feed step S = F * N (N = its circle DDA iterations); a line's S is F << k.
// The first bad frame stops the decoder with an error code, the bad block's N (or the
// previous one) and the frame's offset; the error is only reported by interp_top once every
// good block has played. The golden twin is GoldenTapeDecoder
// (sc_model/golden/golden_decoder.h), whose named steps (process_frame, body_character,
// digit, sign, dot, start_word, finish_word, end_of_block, handoff, fail) follow this
// module decision by decision.
//
// Timing: the reader's signals are registered first (so no logic depends on an input
// combinationally): a frame taken at edge e (frame_valid_i & frame_ready_o) lands in the
// input register and is processed at edge e+1, while the next frame may be taken. The LF
// of a line block puts the decoder in HOLD, the LF of an arc block in ARC until arc_prepare
// is done (max(N, 5W + 5) clocks), then HOLD or ERROR; the block buffer takes a held block
// at the first edge where it is empty (blk_ready_i). frame_ready_o is low while the input
// register is full and cannot be processed at the next edge (ARC, HOLD), and after an
// error. tape_end_i (registered) with no frame waiting in LEADER/BODY/COMMENT is a
// truncated tape.
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
  parameter int OffsetWidth    = 32
) (
  input  logic                   clk_i,
  input  logic                   rst_ni,
  // Tape reader.
  input  logic [7:0]             frame_i,
  input  logic                   frame_valid_i,
  input  logic                   tape_end_i,
  output logic                   frame_ready_o,
  // The decoded motion block, valid while held; taken at an edge with blk_ready_i.
  output logic                   blk_valid_o,
  input  logic                   blk_ready_i,
  output logic [SeqWidth-1:0]    blk_n_o,
  output logic [1:0]             blk_motion_o,
  output logic [IncWidth-1:0]    blk_dx_o,
  output logic                   blk_dx_neg_o,
  output logic [IncWidth-1:0]    blk_dy_o,
  output logic                   blk_dy_neg_o,
  output logic [IncWidth-1:0]    blk_i_o,
  output logic [IncWidth-1:0]    blk_j_o,
  // The feed generator's step S: F << k for a line, F * N for an arc (N < 2^(W+1)).
  output logic [FeedWidth+IncWidth:0]   blk_step_o,
  // k of the block: the line DDA's (bit length of max(|dx|, |dy|)) or the circle DDA's (of
  // the largest coordinate about the centre); for an arc, whether |x|, |y| grow.
  output logic [$clog2(IncWidth+1)-1:0] blk_k_o,
  output logic                   blk_grow_x_o,
  output logic                   blk_grow_y_o,
  // End of program decoded and its last block handed over; trailing frames are checked.
  output logic                   end_o,
  // The reader has delivered every frame (tape_end_i, registered).
  output logic                   tape_ended_o,
  // An error is held (the decoder has stopped).
  output logic                   err_o,
  output logic [3:0]             err_code_o,
  output logic [SeqWidth-1:0]    err_block_o,
  output logic [OffsetWidth-1:0] err_offset_o
);

  // The number accumulator holds any word's value; a digit is checked against the word's
  // limit in NumWidth + 4 bits (num * 10 + 9 cannot overflow that).
  localparam int NumWidth0 = IncWidth > FeedWidth ? IncWidth : FeedWidth;
  localparam int NumWidth1 = NumWidth0 > SeqWidth ? NumWidth0 : SeqWidth;
  localparam int NumWidth  = NumWidth1 > 7 ? NumWidth1 : 7;
  localparam int WideWidth = NumWidth + 4;

  localparam logic [WideWidth-1:0] IncLimit  = {{(WideWidth - IncWidth){1'b0}}, {IncWidth{1'b1}}};
  localparam logic [WideWidth-1:0] FeedLimit = {{(WideWidth - FeedWidth){1'b0}}, {FeedWidth{1'b1}}};
  localparam logic [WideWidth-1:0] SeqLimit  = {{(WideWidth - SeqWidth){1'b0}}, {SeqWidth{1'b1}}};
  localparam logic [WideWidth-1:0] CodeLimit = WideWidth'(99);  // G and M codes
  localparam logic [WideWidth-1:0] CodeMask  = WideWidth'(127);
  localparam int KWidth = $clog2(IncWidth + 1);
  localparam int StepWidth = FeedWidth + IncWidth + 1;
  localparam logic [3:0] FracCount     = 4'(FracDigits);
  localparam logic [3:0] FeedFracCount = 4'(FeedFracDigits);



  typedef enum logic [2:0] {
    StLeader  = 3'd0,  // before '%': frames skipped
    StBody    = 3'd1,  // reading blocks
    StComment = 3'd2,  // inside ( ... )
    StHold    = 3'd3,  // a decoded motion block waits for the block buffer
    StEnd     = 3'd4,  // after the end block: only % NUL CR LF space
    StError   = 3'd5,  // stopped on an error
    StArc     = 3'd6   // an arc block is checked and its iterations counted (arc_prepare)
  } state_e;

  typedef enum logic [3:0] {
    WordNone = 4'd0, WordN = 4'd1, WordG = 4'd2, WordM = 4'd3, WordX = 4'd4,
    WordY = 4'd5, WordI = 4'd6, WordJ = 4'd7, WordF = 4'd8
  } word_e;

  typedef enum logic [1:0] {
    NumStart  = 2'd0,  // right after the letter: a sign or a digit may come
    NumSigned = 2'd1,  // after the sign: a digit must come
    NumInt    = 2'd2,  // integer digits
    NumFrac   = 2'd3   // after '.': fraction digits
  } num_e;

  state_e state_q, state_d;
  // Input register: in_frame_q is a frame taken from the reader and not processed yet
  // (in_valid_q); tape_end_q is tape_end_i one clock late; ready_q is frame_ready_o.
  logic [7:0] in_frame_q, in_frame_d;
  logic       in_valid_q, in_valid_d, tape_end_q, ready_q, ready_d;
  // Offset of the next frame: the offset reported for an error in the frame being taken.
  logic [OffsetWidth-1:0] frame_count_q, frame_count_d;

  // The word being read: its letter, number syntax state, magnitude, sign, the count of
  // fraction digits read and the offset of its letter (for errors found at the word's end).
  word_e                  word_q, word_d;
  num_e                   num_state_q, num_state_d;
  logic [NumWidth-1:0]    num_q, num_d;
  logic                   neg_q, neg_d;
  logic [3:0]             frac_count_q, frac_count_d;
  logic [OffsetWidth-1:0] word_offset_q, word_offset_d;

  // Block assembly. n_q is the last N read (never cleared: a block without N carries the
  // previous one); motion_q (1 = G01, 2 = G02, 3 = G03) and feed_q are modal (G01 and
  // "no feed" after reset).
  logic [SeqWidth-1:0]  n_q, n_d;
  logic [1:0]           motion_q, motion_d;
  logic [FeedWidth-1:0] feed_q, feed_d;
  logic [IncWidth-1:0]  dx_q, dx_d, dy_q, dy_d, i_q, i_d, j_q, j_d;
  logic                 dx_neg_q, dx_neg_d, dy_neg_q, dy_neg_d;
  logic                 i_neg_q, i_neg_d, j_neg_q, j_neg_d;
  // k of the held block: for a line the bit length of (|dx| | |dy|) = bit length of
  // max(|dx|, |dy|) (the line DDA runs 2^k iterations), computed at the LF; for an arc the
  // circle DDA's k and the growth of |x|, |y|, from arc_prepare's geometry when the arc is
  // ready. So the player has nothing to compute at the load.
  logic [KWidth-1:0]    k_q, k_d;
  logic                 grow_x_q, grow_x_d, grow_y_q, grow_y_d;
  // Per-block flags: an N word was read; any word was read; the block moves (X/Y/I/J or
  // a motion G); the block ends the program (M02/M30).
  logic n_seen_q, n_seen_d, any_word_q, any_word_d;
  logic motion_blk_q, motion_blk_d, end_blk_q, end_blk_d;

  // The error found (valid in StError).
  logic [3:0]             err_code_q, err_code_d;
  logic [SeqWidth-1:0]    err_block_q, err_block_d;
  logic [OffsetWidth-1:0] err_offset_q, err_offset_d;

  // Combinational helpers.
  logic                   take;         // the frame in the input register is processed
  logic                   update;       // the parser's registers change at this edge
  state_e                 state_next;   // the state after this edge
  logic                   tape_cut;     // truncated tape found at this edge
  logic [6:0]             ch;           // its character
  logic                   fail;         // an error is found at this edge
  logic [3:0]             fail_code;
  logic [OffsetWidth-1:0] fail_offset;
  logic                   word_ok;      // the word ended by this frame was committed
  logic                   signed_word, fractional_word, word_complete;
  logic [3:0]             frac_limit;
  logic [WideWidth-1:0]   limit, num_next;  // limit: the word's 2^w - 1 (127 for G and M)
  // The arc block being prepared (StArc): result in the clock with arc_done. in_arc is
  // its own signal because Icarus 11 mistypes an enum literal used in a port connection.
  logic                   in_arc, arc_done, arc_err, arc_grow_x, arc_grow_y;
  logic [3:0]             arc_code;
  logic [StepWidth-1:0]   arc_step;
  logic [KWidth-1:0]      arc_k;

  // Bit length of a value (position of its highest 1 plus one; 0 for 0).
  function automatic logic [KWidth-1:0] bit_length(input logic [IncWidth-1:0] value);
    bit_length = '0;
    for (int b = 0; b < IncWidth; b++) begin
      if (value[b]) bit_length = KWidth'(b + 1);
    end
  endfunction

  assign in_arc = state_q == StArc;
  assign take = in_valid_q && state_q != StHold && !in_arc && state_q != StError;
  // The reader has delivered every frame, none waits, and the program has not ended.
  assign tape_cut = tape_end_q && !in_valid_q &&
                    (state_q == StLeader || state_q == StBody || state_q == StComment);
  assign ch   = in_frame_q[6:0];
  assign update = take || in_arc || state_q == StHold || tape_cut;
  assign state_next = update ? state_d : state_q;

  always_comb begin
    // Clocks without an update (most clocks: the reader is slow) evaluate nothing here:
    // the parser's registers keep their values (the always_ff's enable), so the next-state
    // values are don't-care ('x): the verilated model skips them (fast) and synthesis folds
    // the 'x away (no gate per next-state bit).
    {state_d, frame_count_d, word_d, num_state_d, num_d, neg_d, frac_count_d, word_offset_d,
     n_d, motion_d, feed_d, dx_d, dx_neg_d, dy_d, dy_neg_d, i_d, i_neg_d, j_d, j_neg_d,
     n_seen_d, any_word_d, motion_blk_d, end_blk_d, err_code_d, err_block_d, err_offset_d, k_d,
     grow_x_d, grow_y_d, fail, fail_code, fail_offset, word_ok, signed_word, fractional_word,
     frac_limit, limit, word_complete, num_next} = 'x;
    if (update) begin
      state_d       = state_q;
      frame_count_d = frame_count_q;
      word_d        = word_q;
      num_state_d   = num_state_q;
      num_d         = num_q;
      neg_d         = neg_q;
      frac_count_d  = frac_count_q;
      word_offset_d = word_offset_q;
      n_d           = n_q;
      motion_d      = motion_q;
      feed_d        = feed_q;
      dx_d = dx_q;  dx_neg_d = dx_neg_q;
      dy_d = dy_q;  dy_neg_d = dy_neg_q;
      i_d  = i_q;   i_neg_d  = i_neg_q;
      j_d  = j_q;   j_neg_d  = j_neg_q;
      n_seen_d      = n_seen_q;
      any_word_d    = any_word_q;
      motion_blk_d  = motion_blk_q;
      end_blk_d     = end_blk_q;
      err_code_d    = err_code_q;
      err_block_d   = err_block_q;
      err_offset_d  = err_offset_q;
      k_d           = k_q;
      grow_x_d      = grow_x_q;
      grow_y_d      = grow_y_q;
      fail          = 1'b0;
      fail_code     = interp_pkg::ErrParity;
      fail_offset   = frame_count_q;
      word_ok       = 1'b1;
      signed_word     = 1'b0;
      fractional_word = 1'b0;
      frac_limit      = FracCount;
      limit           = IncLimit;
      word_complete   = 1'b0;
      num_next        = '0;

      if (take) begin
        frame_count_d = frame_count_q + 1'b1;
        // Properties of the word being read (computed only when a frame is processed).
        signed_word     = word_q == WordX || word_q == WordY || word_q == WordI || word_q == WordJ;
        fractional_word = signed_word || word_q == WordF;
        frac_limit      = word_q == WordF ? FeedFracCount : FracCount;
        unique case (word_q)
          WordN:        limit = SeqLimit;
          WordG, WordM: limit = CodeMask;
          WordF:        limit = FeedLimit;
          default:      limit = IncLimit;
        endcase
        word_complete = fractional_word ? (num_state_q == NumFrac && frac_count_q == frac_limit)
                                        : (num_state_q == NumInt);
        num_next = {1'b0, num_q, 3'b000} + {2'b00, num_q, 1'b0} + WideWidth'(ch[3:0]);  // *10 + d
        if (^in_frame_q) begin
          fail = 1'b1;  // odd parity
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
              if (ch == interp_pkg::ChSpace || ch == interp_pkg::ChCr) begin
                // ignored everywhere, even inside a number
              end else if (ch >= interp_pkg::ChZero && ch <= interp_pkg::ChNine) begin
                if (word_q == WordNone) begin
                  fail = 1'b1;
                  fail_code = interp_pkg::ErrMalformedNumber;
                end else if (num_state_q == NumFrac && frac_count_q == frac_limit) begin
                  fail = 1'b1;
                  fail_code = interp_pkg::ErrMalformedNumber;  // one fraction digit too many
                end else if ((num_next & ~limit) != '0 ||
                             ((word_q == WordG || word_q == WordM) &&
                              num_next[6:0] > CodeLimit[6:0])) begin
                  // above the word's limit: a mask 2^w - 1 (one OR of the high bits), or 99
                  fail = 1'b1;
                  fail_code = interp_pkg::ErrValueTooWide;
                end else begin
                  num_d = num_next[NumWidth-1:0];
                  if (num_state_q == NumFrac) frac_count_d = frac_count_q + 1'b1;
                  else num_state_d = NumInt;
                end
              end else if (ch == interp_pkg::ChPlus || ch == interp_pkg::ChMinus) begin
                if (!signed_word || num_state_q != NumStart) begin
                  fail = 1'b1;
                  fail_code = interp_pkg::ErrMalformedNumber;
                end else begin
                  neg_d = ch == interp_pkg::ChMinus;
                  num_state_d = NumSigned;
                end
              end else if (ch == interp_pkg::ChDot) begin
                if (!fractional_word || num_state_q != NumInt) begin
                  fail = 1'b1;
                  fail_code = interp_pkg::ErrMalformedNumber;
                end else begin
                  num_state_d = NumFrac;
                end
              end else begin
                // Any other character ends the word being read: check and commit it first.
                if (word_q != WordNone) begin
                  word_d = WordNone;
                  if (!word_complete) begin
                    word_ok = 1'b0;
                    fail_code = interp_pkg::ErrMalformedNumber;
                  end else begin
                    unique case (word_q)
                      WordN: n_d = num_q[SeqWidth-1:0];
                      WordG: begin
                        if (num_q >= NumWidth'(1) && num_q <= NumWidth'(3)) begin
                          motion_d = num_q[1:0];  // G01, G02, G03
                          motion_blk_d = 1'b1;
                        end else if (!(num_q == NumWidth'(17) || num_q == NumWidth'(21) ||
                                       num_q == NumWidth'(91) || num_q == NumWidth'(93))) begin
                          word_ok = 1'b0;
                          fail_code = interp_pkg::ErrUnsupportedCode;
                        end
                      end
                      WordM: begin
                        if (num_q == NumWidth'(2) || num_q == NumWidth'(30)) begin
                          end_blk_d = 1'b1;
                        end else begin
                          word_ok = 1'b0;
                          fail_code = interp_pkg::ErrUnsupportedCode;
                        end
                      end
                      WordX: begin
                        dx_d = num_q[IncWidth-1:0];
                        dx_neg_d = neg_q;
                        motion_blk_d = 1'b1;
                      end
                      WordY: begin
                        dy_d = num_q[IncWidth-1:0];
                        dy_neg_d = neg_q;
                        motion_blk_d = 1'b1;
                      end
                      WordI: begin
                        i_d = num_q[IncWidth-1:0];
                        i_neg_d = neg_q;
                        motion_blk_d = 1'b1;
                      end
                      WordJ: begin
                        j_d = num_q[IncWidth-1:0];
                        j_neg_d = neg_q;
                        motion_blk_d = 1'b1;
                      end
                      default: feed_d = num_q[FeedWidth-1:0];  // WordF
                    endcase
                  end
                  if (!word_ok) begin
                    fail = 1'b1;
                    fail_offset = word_offset_q;
                  end
                end
                // Then the character itself.
                if (word_ok) begin
                  if (ch == interp_pkg::ChN || ch == interp_pkg::ChG || ch == interp_pkg::ChM ||
                      ch == interp_pkg::ChX || ch == interp_pkg::ChY || ch == interp_pkg::ChI ||
                      ch == interp_pkg::ChJ || ch == interp_pkg::ChF) begin
                    if (ch == interp_pkg::ChN && n_seen_q) begin
                      fail = 1'b1;
                      // a second N: the LF is missing
                      fail_code = interp_pkg::ErrMissingEndOfBlock;
                    end else begin
                      unique case (ch)
                        interp_pkg::ChN:     word_d = WordN;
                        interp_pkg::ChG:     word_d = WordG;
                        interp_pkg::ChM:     word_d = WordM;
                        interp_pkg::ChX:     word_d = WordX;
                        interp_pkg::ChY:     word_d = WordY;
                        interp_pkg::ChI:     word_d = WordI;
                        interp_pkg::ChJ:     word_d = WordJ;
                        default: word_d = WordF;
                      endcase
                      if (ch == interp_pkg::ChN) n_seen_d = 1'b1;
                      any_word_d    = 1'b1;
                      num_state_d   = NumStart;
                      num_d         = '0;
                      neg_d         = 1'b0;
                      frac_count_d  = '0;
                      word_offset_d = frame_count_q;
                    end
                  end else if (ch == interp_pkg::ChLf) begin
                    if (motion_blk_d) begin
                      if (feed_d == '0) begin
                        fail = 1'b1;
                        fail_code = interp_pkg::ErrMissingFeed;
                      end else begin
                        // A line waits for the buffer (cleared at the handoff); an arc is
                        // prepared first.
                        if (motion_d == interp_pkg::MotionLine) state_d = StHold;
                        else state_d = StArc;
                        k_d = bit_length(dx_d | dy_d);
                      end
                    end else begin
                      if (end_blk_d) state_d = StEnd;
                      n_seen_d = 1'b0;  any_word_d = 1'b0;  motion_blk_d = 1'b0;  end_blk_d = 1'b0;
                      dx_d = '0;  dy_d = '0;  i_d = '0;  j_d = '0;
                      dx_neg_d = 1'b0;  dy_neg_d = 1'b0;  i_neg_d = 1'b0;  j_neg_d = 1'b0;
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
            default: ;  // StHold, StArc, StError: no frame is processed
          endcase
        end
      end else if (state_q == StArc) begin
        if (arc_done) begin
          if (arc_err) begin
            fail = 1'b1;
            fail_code = arc_code;
            fail_offset = frame_count_q - 1'b1;  // the block's LF, the last frame processed
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
          n_seen_d = 1'b0;  any_word_d = 1'b0;  motion_blk_d = 1'b0;  end_blk_d = 1'b0;
          dx_d = '0;  dy_d = '0;  i_d = '0;  j_d = '0;
          dx_neg_d = 1'b0;  dy_neg_d = 1'b0;  i_neg_d = 1'b0;  j_neg_d = 1'b0;
        end
      end else if (tape_cut) begin
        fail = 1'b1;
        fail_code = interp_pkg::ErrTruncatedTape;  // at the offset of the frame that never came
      end

      if (fail) begin
        state_d      = StError;
        err_code_d   = fail_code;
        err_block_d  = n_d;  // includes an N committed by this frame
        err_offset_d = fail_offset;
      end
    end
  end

  // Input register: a new frame is taken while the previous one is processed. Kept apart
  // from the parser above, which then depends on registers only (a simulator re-evaluates
  // input-dependent logic on every input change).
  always_comb begin
    in_frame_d = in_frame_q;
    in_valid_d = in_valid_q && !take;
    if (frame_valid_i && ready_q) begin
      in_frame_d = frame_i;
      in_valid_d = 1'b1;
    end
    ready_d = state_next != StError &&
              !((state_next == StHold || state_next == StArc) && in_valid_d);
  end

  // Arc blocks: the checks and the dry run that counts the circle DDA's iterations N and
  // sums S = F * N. Its result stays in its registers until the next arc starts, i.e. for
  // the whole HOLD that follows.
  arc_prepare #(.IncWidth(IncWidth), .FeedWidth(FeedWidth), .KWidth(KWidth)) u_arc (
    .clk_i, .rst_ni, .run_i(in_arc),
    .dx_i(dx_q), .dx_neg_i(dx_neg_q), .dy_i(dy_q), .dy_neg_i(dy_neg_q),
    .i_i(i_q), .i_neg_i(i_neg_q), .j_i(j_q), .j_neg_i(j_neg_q),
    .ccw_i(motion_q == interp_pkg::MotionArcCcw), .feed_i(feed_q),
    .done_o(arc_done), .err_o(arc_err), .err_code_o(arc_code), .step_o(arc_step),
    .k_o(arc_k), .grow_x_o(arc_grow_x), .grow_y_o(arc_grow_y)
  );

  // The parser's registers change only when a frame is processed, an arc is prepared, a
  // held block is handed over or the tape has ended (update); the input register changes
  // every clock.

  always_ff @(posedge clk_i) begin
    if (!rst_ni) begin
      state_q       <= StLeader;
      in_frame_q    <= '0;
      in_valid_q    <= 1'b0;
      tape_end_q    <= 1'b0;
      ready_q       <= 1'b1;
      frame_count_q <= '0;
      word_q        <= WordNone;
      num_state_q   <= NumStart;
      num_q         <= '0;
      neg_q         <= 1'b0;
      frac_count_q  <= '0;
      word_offset_q <= '0;
      n_q           <= '0;
      motion_q      <= interp_pkg::MotionLine;
      feed_q        <= '0;
      dx_q <= '0;  dx_neg_q <= 1'b0;
      dy_q <= '0;  dy_neg_q <= 1'b0;
      i_q  <= '0;  i_neg_q  <= 1'b0;
      j_q  <= '0;  j_neg_q  <= 1'b0;
      k_q           <= '0;
      grow_x_q      <= 1'b0;
      grow_y_q      <= 1'b0;
      n_seen_q      <= 1'b0;
      any_word_q    <= 1'b0;
      motion_blk_q  <= 1'b0;
      end_blk_q     <= 1'b0;
      err_code_q    <= '0;
      err_block_q   <= '0;
      err_offset_q  <= '0;
    end else begin
      in_frame_q    <= in_frame_d;
      in_valid_q    <= in_valid_d;
      tape_end_q    <= tape_end_i;
      ready_q       <= ready_d;
      if (update) begin
          state_q       <= state_d;
          frame_count_q <= frame_count_d;
          word_q        <= word_d;
          num_state_q   <= num_state_d;
          num_q         <= num_d;
          neg_q         <= neg_d;
          frac_count_q  <= frac_count_d;
          word_offset_q <= word_offset_d;
          n_q           <= n_d;
          motion_q      <= motion_d;
          feed_q        <= feed_d;
          dx_q <= dx_d;  dx_neg_q <= dx_neg_d;
          dy_q <= dy_d;  dy_neg_q <= dy_neg_d;
          i_q  <= i_d;   i_neg_q  <= i_neg_d;
          j_q  <= j_d;   j_neg_q  <= j_neg_d;
          k_q           <= k_d;
          grow_x_q      <= grow_x_d;
          grow_y_q      <= grow_y_d;
          n_seen_q      <= n_seen_d;
          any_word_q    <= any_word_d;
          motion_blk_q  <= motion_blk_d;
          end_blk_q     <= end_blk_d;
          err_code_q    <= err_code_d;
          err_block_q   <= err_block_d;
          err_offset_q  <= err_offset_d;
        end
    end
  end

  assign frame_ready_o = ready_q;
  assign blk_valid_o   = state_q == StHold;
  assign blk_n_o       = n_q;
  assign blk_motion_o  = motion_q;
  assign blk_dx_o      = dx_q;
  assign blk_dx_neg_o  = dx_neg_q;
  assign blk_dy_o      = dy_q;
  assign blk_dy_neg_o  = dy_neg_q;
  assign blk_i_o       = i_q;
  assign blk_j_o       = j_q;
  assign blk_step_o    = motion_q == interp_pkg::MotionLine ? StepWidth'(feed_q) << k_q : arc_step;
  assign blk_k_o       = k_q;
  assign blk_grow_x_o  = grow_x_q;
  assign blk_grow_y_o  = grow_y_q;
  assign end_o         = state_q == StEnd;
  assign tape_ended_o  = tape_end_q;
  assign err_o         = state_q == StError;
  assign err_code_o    = err_code_q;
  assign err_block_o   = err_block_q;
  assign err_offset_o  = err_offset_q;

endmodule
