// Tape decoder, word parser (docs/interpolator.md 3.2): characters -> words N G M X Y I J F
// with their numbers, in the strict syntax where every rule is one error.
//
// What: for each body character (char_valid_i: a frame of the block body that passed the
// parity check) it either extends the number being read (digit, sign, decimal point, checked
// against the word's syntax and its register's limit), ignores it (space, CR), or ends the
// word: any other character is a delimiter (delimiter_o). At a delimiter the word being read
// is checked to be complete and handed to the block assembly (word_end_o with its letter,
// value, sign and the offset of its letter); an address letter then starts the next word
// (word_start_o). A syntax error (err_o) names its code and offset: the character's, or the
// word's letter for an incomplete word (err_at_word_o).
// Idea: the number is read as an integer in basic length units: exactly FracDigits fraction
// digits for X Y I J (FeedFracDigits for F), none for N G M, so no scaling is ever needed.
// A digit is checked against the word's limit 2^w - 1 in NumWidth + 4 bits (num * 10 + 9
// cannot overflow them): one OR over the high bits, and <= 99 for the G and M codes.
// With BitSerial (the board's choice), x10 + d is not one adder but a pass of NumWidth
// clocks on a one-bit adder (see "Bit-serial digit pass" below): the digit's syntax is
// checked at its edge, its limit at the pass's last edge (value_err_o), and no character is
// taken while the pass runs (busy_o): a frame comes every ~1000 clocks from a reader at
// 1000 characters/s and 1 MHz, so the pass is hidden.
// The block assembly (tape_decoder.sv) gives the words their meaning; after an error the
// decoder stops, and this module's registers no longer matter.
// Golden twin: the section "Word parser" of GoldenTapeDecoder
// (sc_model/golden/tape_decoder.cpp: digit(), sign(), dot(), start_word(), word_complete()).
module tape_word_parser #(
  parameter int IncWidth       = 16,
  parameter int FracDigits     = 3,
  parameter int FeedWidth      = 32,
  parameter int FeedFracDigits = 3,
  parameter int SeqWidth       = 20,
  parameter int OffsetWidth    = 32,
  // Width of the number read: the widest register a word fills (IncWidth, FeedWidth,
  // SeqWidth) and at least 7 bits (the G and M codes).
  parameter int NumWidth       = 32,
  // x10 + d on one adder of NumWidth + 4 bits per digit (0) or bit-serially (1).
  parameter bit BitSerial      = 1'b0
) (
  input  logic                   clk_i,
  input  logic                   rst_ni,
  // A character of the block body is processed at this edge (parity checked), its offset.
  input  logic                   char_valid_i,
  input  logic [6:0]             char_i,
  input  logic [OffsetWidth-1:0] offset_i,
  // The character breaks the number syntax or the word's limit (valid with char_valid_i),
  // with the error's offset: the character's, or (err_at_word_o) the word's letter
  // (word_offset_o) for an incomplete word.
  output logic                   err_o,
  output logic [interp_pkg::ErrCodeWidth-1:0] err_code_o,
  output logic                   err_at_word_o,
  // The character ends the word being read, if any (not a digit, sign, point or blank).
  output logic                   delimiter_o,
  // At a delimiter without err_o: a complete word ends (its letter interp_pkg::ChN ...,
  // value, sign and its letter's offset); an address letter starts the next word.
  output logic                   word_end_o,
  output logic [6:0]             word_letter_o,
  output logic [NumWidth-1:0]    word_value_o,
  output logic                   word_neg_o,
  output logic [OffsetWidth-1:0] word_offset_o,
  output logic                   word_start_o,
  // BitSerial: a digit's pass runs at this edge (no character is taken), and will after it;
  // at the pass's last edge, the number went over its word's limit (ErrValueTooWide, at the
  // digit). Constant 0 without BitSerial.
  output logic                   busy_o,
  output logic                   busy_next_o,
  output logic                   value_err_o
);

  localparam int WideWidth = NumWidth + 4;
  localparam logic [WideWidth-1:0] IncLimit  = {{(WideWidth - IncWidth){1'b0}}, {IncWidth{1'b1}}};
  localparam logic [WideWidth-1:0] FeedLimit = {{(WideWidth - FeedWidth){1'b0}}, {FeedWidth{1'b1}}};
  localparam logic [WideWidth-1:0] SeqLimit  = {{(WideWidth - SeqWidth){1'b0}}, {SeqWidth{1'b1}}};
  localparam logic [WideWidth-1:0] CodeLimit = WideWidth'(99);  // G and M codes
  localparam logic [WideWidth-1:0] CodeMask  = WideWidth'(127);
  localparam logic [3:0] FracCount     = 4'(FracDigits);
  localparam logic [3:0] FeedFracCount = 4'(FeedFracDigits);

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

  // The word being read: its letter, number syntax state, magnitude, sign, the count of
  // fraction digits read and the offset of its letter (for errors found at the word's end).
  word_e                  word_q, word_d;
  num_e                   num_state_q, num_state_d;
  logic [NumWidth-1:0]    num_q, num_d;
  logic                   neg_q, neg_d;
  logic [3:0]             frac_count_q, frac_count_d;
  logic [OffsetWidth-1:0] word_offset_q, word_offset_d;

  logic                 is_digit, is_sign, is_dot, is_blank, is_letter;
  logic                 signed_word, fractional_word, word_complete;
  logic [3:0]           frac_limit;
  logic [WideWidth-1:0] limit, num_next;  // limit: the word's 2^w - 1 (127 for G and M)
  word_e                letter_word;      // the word an address letter starts

  // The character's class, the word's properties, the checks and the next word, in one
  // block. Clocks without a body character (most clocks: the reader is slow) evaluate
  // nothing here: the registers keep their values (the always_ff's enable) and the outputs
  // are not used (tape_decoder.sv reads them only with char_valid_i), so both are don't-care
  // ('x), which the verilated model skips (no 36-bit x10 per clock) and synthesis folds away.
  always_comb begin
    {word_d, num_state_d, num_d, neg_d, frac_count_d, word_offset_d, is_blank, is_digit,
     is_sign, is_dot, is_letter, letter_word, signed_word, fractional_word, frac_limit, limit,
     word_complete, num_next, err_o, err_code_o, err_at_word_o, delimiter_o, word_end_o,
     word_start_o} = 'x;
    if (char_valid_i) begin
      is_blank  = char_i == interp_pkg::ChSpace || char_i == interp_pkg::ChCr;
      // '0' to '9' (0x30 to 0x39) by its bits, not as a range compare: synthesis makes
      // a compare a carry chain, and this one starts the decoder's longest path.
      is_digit  = char_i[6:4] == interp_pkg::ChZero[6:4] &&
                  (!char_i[3] || char_i[2:1] == 2'b00);
      is_sign   = char_i == interp_pkg::ChPlus || char_i == interp_pkg::ChMinus;
      is_dot    = char_i == interp_pkg::ChDot;
      is_letter = 1'b1;
      unique case (char_i)
        interp_pkg::ChN: letter_word = WordN;
        interp_pkg::ChG: letter_word = WordG;
        interp_pkg::ChM: letter_word = WordM;
        interp_pkg::ChX: letter_word = WordX;
        interp_pkg::ChY: letter_word = WordY;
        interp_pkg::ChI: letter_word = WordI;
        interp_pkg::ChJ: letter_word = WordJ;
        interp_pkg::ChF: letter_word = WordF;
        default: begin
          letter_word = WordNone;
          is_letter   = 1'b0;
        end
      endcase
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
      if (!BitSerial)
        num_next = {1'b0, num_q, 3'b000} + {2'b00, num_q, 1'b0} + WideWidth'(char_i[3:0]);  // *10 + d
      delimiter_o  = !(is_blank || is_digit || is_sign || is_dot);
      word_end_o   = delimiter_o && word_q != WordNone && word_complete;
      word_start_o = delimiter_o && is_letter;

      word_d        = word_q;
      num_state_d   = num_state_q;
      num_d         = num_q;
      neg_d         = neg_q;
      frac_count_d  = frac_count_q;
      word_offset_d = word_offset_q;
      err_o         = 1'b0;
      err_code_o    = interp_pkg::ErrMalformedNumber;
      err_at_word_o = 1'b0;
      if (is_digit) begin
        if (word_q == WordNone || (num_state_q == NumFrac && frac_count_q == frac_limit)) begin
          err_o = 1'b1;  // a digit outside a word, or one fraction digit too many
        end else if (!BitSerial && ((num_next & ~limit) != '0 ||
                     ((word_q == WordG || word_q == WordM) && num_next[6:0] > CodeLimit[6:0]))) begin
          err_o = 1'b1;  // above the word's limit: a mask 2^w - 1 (one OR of the high bits), or 99
          err_code_o = interp_pkg::ErrValueTooWide;
        end else begin
          // BitSerial: num_q is unchanged here; the digit's pass starts (start_pass).
          if (!BitSerial) num_d = num_next[NumWidth-1:0];
          if (num_state_q == NumFrac) frac_count_d = frac_count_q + 1'b1;
          else num_state_d = NumInt;
        end
      end else if (is_sign) begin
        if (!signed_word || num_state_q != NumStart) begin
          err_o = 1'b1;
        end else begin
          neg_d = char_i == interp_pkg::ChMinus;
          num_state_d = NumSigned;
        end
      end else if (is_dot) begin
        if (!fractional_word || num_state_q != NumInt) err_o = 1'b1;
        else num_state_d = NumFrac;
      end else if (!is_blank) begin
        // A delimiter: the word being read ends (complete, or an error at its letter); an
        // address letter starts the next one.
        if (word_q != WordNone && !word_complete) begin
          err_o = 1'b1;
          err_at_word_o = 1'b1;
        end
        word_d = letter_word;
        if (is_letter) begin
          num_state_d   = NumStart;
          num_d         = '0;
          neg_d         = 1'b0;
          frac_count_d  = '0;
          word_offset_d = offset_i;
        end
      end
    end
  end

  always_ff @(posedge clk_i) begin
    if (!rst_ni) begin
      word_q        <= WordNone;
      num_state_q   <= NumStart;
      neg_q         <= 1'b0;
      frac_count_q  <= '0;
      word_offset_q <= '0;
    end else if (char_valid_i) begin
      word_q        <= word_d;
      num_state_q   <= num_state_d;
      neg_q         <= neg_d;
      frac_count_q  <= frac_count_d;
      word_offset_q <= word_offset_d;
    end
  end

  // num_q: set by a character (char_valid_i), or shifted by a digit's pass (BitSerial).
  logic pass_shift, pass_bit;
  always_ff @(posedge clk_i) begin
    if (!rst_ni) num_q <= '0;
    else if (char_valid_i) num_q <= num_d;
    else if (pass_shift) num_q <= {pass_bit, num_q[NumWidth-1:1]};
  end

  // Bit-serial digit pass (BitSerial): num * 10 + d = (num << 3) + (num << 1) + d, LSB first.
  // Schedule: the digit's edge e (start_pass) loads the digit and clears the adder; edge
  // e + 1 + i (i = 0 .. NumWidth - 1) forms bit i of the result from bit i of the digit,
  // num's bits i - 1 and i - 3 (hist_q: the bits num_q has shifted out) and a carry of 0 to
  // 2, and shifts it in at num_q's top, so after NumWidth edges num_q holds the new number
  // in place. A result bit at or above the word's width sets over_q; what is left above
  // bit NumWidth - 1 (the carry and the old number's three top bits) must be 0; G and M
  // also compare the low 7 bits with 99 (LSB first: gt_q). The last edge (e + NumWidth)
  // reports value_err_o; the decoder takes no character from e + 1 to e + NumWidth.
  if (BitSerial) begin : g_serial_digit
    localparam int BitWidth = $clog2(NumWidth);
    localparam logic [6:0] CodeMax = 7'd99;
    logic [BitWidth-1:0] bit_q;
    logic [3:0]          digit_q;
    logic [2:0]          hist_q;   // num's bits i - 1, i - 2, i - 3 at [0], [1], [2]
    logic [1:0]          carry_q;
    logic                busy_q, over_q, gt_q, gt_d, start_pass, last, past_width;
    logic [2:0]          sum;
    logic [BitWidth:0]   width;    // the word's register width (7 for G and M)

    assign start_pass = char_valid_i && is_digit && !err_o;
    assign last       = bit_q == BitWidth'(NumWidth - 1);
    always_comb begin
      unique case (word_q)
        WordN:        width = (BitWidth + 1)'(SeqWidth);
        WordG, WordM: width = (BitWidth + 1)'(7);
        WordF:        width = (BitWidth + 1)'(FeedWidth);
        default:      width = (BitWidth + 1)'(IncWidth);
      endcase
    end
    assign sum        = {2'b00, hist_q[0]} + {2'b00, hist_q[2]} + {2'b00, digit_q[0]} +
                        {1'b0, carry_q};
    assign past_width = {1'b0, bit_q} >= width;
    // Result bits 0..6 against 99: greater at this bit, or equal here and greater below.
    assign gt_d = bit_q < BitWidth'(7) ? (sum[0] && !CodeMax[bit_q[2:0]]) ||
                                         (sum[0] == CodeMax[bit_q[2:0]] && gt_q)
                                       : gt_q;

    always_ff @(posedge clk_i) begin
      if (!rst_ni) begin
        busy_q <= 1'b0;
        {bit_q, digit_q, hist_q, carry_q, over_q, gt_q} <= '0;
      end else if (start_pass) begin
        busy_q  <= 1'b1;
        bit_q   <= '0;
        digit_q <= char_i[3:0];
        {hist_q, carry_q, over_q, gt_q} <= '0;
      end else if (busy_q) begin
        bit_q   <= bit_q + 1'b1;
        digit_q <= digit_q >> 1;
        hist_q  <= {hist_q[1:0], num_q[0]};
        carry_q <= sum[2:1];
        over_q  <= over_q || (sum[0] && past_width);
        gt_q    <= gt_d;
        if (last) busy_q <= 1'b0;
      end
    end

    assign pass_shift  = busy_q;
    assign pass_bit    = sum[0];
    assign busy_o      = busy_q;
    assign busy_next_o = start_pass || (busy_q && !last);
    assign value_err_o = busy_q && last &&
                         (over_q || (sum[0] && past_width) || sum[2:1] != '0 ||
                          {hist_q[1:0], num_q[0]} != '0 ||
                          ((word_q == WordG || word_q == WordM) && gt_d));
  end else begin : g_parallel_digit
    assign pass_shift  = 1'b0;
    assign pass_bit    = 1'b0;
    assign busy_o      = 1'b0;
    assign busy_next_o = 1'b0;
    assign value_err_o = 1'b0;
  end

  // The word handed over at a delimiter: its letter, as on tape.
  always_comb begin
    unique case (word_q)
      WordN:   word_letter_o = interp_pkg::ChN;
      WordG:   word_letter_o = interp_pkg::ChG;
      WordM:   word_letter_o = interp_pkg::ChM;
      WordX:   word_letter_o = interp_pkg::ChX;
      WordY:   word_letter_o = interp_pkg::ChY;
      WordI:   word_letter_o = interp_pkg::ChI;
      WordJ:   word_letter_o = interp_pkg::ChJ;
      default: word_letter_o = interp_pkg::ChF;  // WordF (WordNone: no word_end_o)
    endcase
  end

  assign word_value_o  = num_q;
  assign word_neg_o    = neg_q;
  assign word_offset_o = word_offset_q;

endmodule
