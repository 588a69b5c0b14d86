// Tape decoder of the golden model; the rules are docs/interpolator.md section 3 and the
// code follows rtl/tape_decoder.sv, tape_frame_input.sv and tape_word_parser.sv decision by
// decision (same priorities, same offsets), in their three sections.
#include "tape_decoder.h"

#include "bit_length.h"

#include <algorithm>

namespace ncinterp {

namespace {

uint64_t low_mask(unsigned bits) { return bits >= 64 ? ~0ull : (1ull << bits) - 1; }

bool odd_parity(uint8_t frame) { return __builtin_parity(frame) != 0; }

}  // namespace

GoldenTapeDecoder::GoldenTapeDecoder(const InterpConfig& cfg)
    : bit_serial_(cfg.serial()),
      circle_mode_(cfg.circle_mode),
      misc_functions_(cfg.misc_functions),
      num_width_(std::max({cfg.inc_width, cfg.feed_width, cfg.seq_width, 7u})),
      frac_digits_(cfg.frac_digits),
      feed_frac_digits_(cfg.feed_frac_digits),
      inc_limit_(low_mask(cfg.inc_width)),
      feed_limit_(low_mask(cfg.feed_width)),
      seq_limit_(low_mask(cfg.seq_width)),
      offset_mask_(static_cast<uint32_t>(low_mask(cfg.offset_width))),
      step_mask_(step_mask(cfg)),
      rapid_step_(cfg.rapid_step_on_port()),
      arc_(cfg.inc_width, cfg.serial()) {}

uint64_t GoldenTapeDecoder::step_mask(const InterpConfig& cfg) {
  const unsigned exact = cfg.feed_width + cfg.inc_width + 1;
  const unsigned job = cfg.modulus_width - SerialDda::player_lead_bits(cfg) + 1;
  return low_mask(std::min(exact, job));
}

void GoldenTapeDecoder::reset() {
  state_ = State::kLeader;
  in_frame_ = 0;
  in_valid_ = false;
  tape_end_q_ = false;
  ready_ = true;
  frame_count_ = 0;
  word_ = Word::kNone;
  num_state_ = Num::kStart;
  num_ = 0;
  neg_ = false;
  frac_count_ = 0;
  word_offset_ = 0;
  digit_pass_ = 0;
  digit_over_ = false;
  block_ = DecodedBlock{};
  block_.motion = 1;
  block_.feed = 0;
  clear_block();
  feed_in_ = false;
  shifts_ = 0;
  arc_.reset();
  err_code_ = TapeError::kNone;
  err_block_ = 0;
  err_offset_ = 0;
}

// ---------------------------------------------------------------------------------------
// Frame input (rtl/tape_frame_input.sv): input register, parity, offset. edge() also
// dispatches the clock to the block assembly, as tape_decoder.sv does.

void GoldenTapeDecoder::edge(const InterpInputs& in, bool buffer_empty) {
  const bool process = in_valid_ && state_ != State::kHold && state_ != State::kPrepare &&
                       state_ != State::kError && digit_pass_ == 0;
  if (process) {
    process_frame(in_frame_);
  } else if (digit_pass_ > 0) {  // a digit's pass (BitSerial); its verdict at the last edge
    if (--digit_pass_ == 0 && digit_over_)
      fail(TapeError::kValueTooWide, (frame_count_ - 1) & offset_mask_);  // the digit
  } else if (state_ == State::kPrepare) {
    prepare_edge();
  } else if (state_ == State::kHold) {
    if (buffer_empty) handoff();
  } else if (tape_end_q_ && !in_valid_ && state_ <= State::kComment) {
    fail(TapeError::kTruncatedTape, frame_count_);  // the frame that never came
  }
  // Input register: a new frame is taken while the previous one is processed.
  in_valid_ = in_valid_ && !process;
  if (in.frame_valid && ready_) {
    in_frame_ = in.frame;
    in_valid_ = true;
  }
  tape_end_q_ = in.tape_end;
  ready_ = state_ != State::kError &&
           !((state_ == State::kHold || state_ == State::kPrepare || digit_pass_ > 0) && in_valid_);
}

void GoldenTapeDecoder::process_frame(uint8_t frame) {
  const uint32_t offset = frame_count_;
  frame_count_ = (frame_count_ + 1) & offset_mask_;
  if (odd_parity(frame)) return fail(TapeError::kParity, offset);
  const char c = static_cast<char>(frame & 0x7f);
  switch (state_) {
    case State::kLeader:
      if (c == '%') state_ = State::kBody;
      return;
    case State::kComment:
      if (c == ')') state_ = State::kBody;
      return;
    case State::kEnd:
      if (!(c == '%' || c == '\0' || c == '\r' || c == '\n' || c == ' '))
        fail(TapeError::kBlockAfterEnd, offset);
      return;
    case State::kBody:
      return body_character(c, offset);
    case State::kHold:
    case State::kPrepare:
    case State::kError:
      return;  // edge() does not process a frame in these states
  }
}

// ---------------------------------------------------------------------------------------
// Word parser (rtl/tape_word_parser.sv): number syntax and each word's limit.

uint64_t GoldenTapeDecoder::limit(Word w) const {
  switch (w) {
    case Word::kN: return seq_limit_;
    case Word::kG:
    case Word::kM: return 99;
    case Word::kF: return feed_limit_;
    default: return inc_limit_;
  }
}

unsigned GoldenTapeDecoder::fraction_digits(Word w) const {
  return w == Word::kF ? feed_frac_digits_ : frac_digits_;
}

void GoldenTapeDecoder::digit(unsigned d, uint32_t offset) {
  if (word_ == Word::kNone) return fail(TapeError::kMalformedNumber, offset);
  const bool in_fraction = num_state_ == Num::kFrac;
  if (in_fraction && frac_count_ == fraction_digits(word_))
    return fail(TapeError::kMalformedNumber, offset);
  const uint64_t value = num_ * 10 + d;
  const bool over = value > limit(word_);
  if (bit_serial_) {  // the limit's verdict comes at the pass's last edge
    digit_pass_ = num_width_;
    digit_over_ = over;
  } else if (over) {
    return fail(TapeError::kValueTooWide, offset);
  }
  num_ = value;
  if (in_fraction)
    ++frac_count_;
  else
    num_state_ = Num::kInt;
}

void GoldenTapeDecoder::sign(bool negative, uint32_t offset) {
  const bool signed_word =
      word_ == Word::kX || word_ == Word::kY || word_ == Word::kI || word_ == Word::kJ;
  if (!signed_word || num_state_ != Num::kStart)
    return fail(TapeError::kMalformedNumber, offset);
  neg_ = negative;
  num_state_ = Num::kSigned;
}

void GoldenTapeDecoder::dot(uint32_t offset) {
  const bool fractional = word_ == Word::kX || word_ == Word::kY || word_ == Word::kI ||
                          word_ == Word::kJ || word_ == Word::kF;
  if (!fractional || num_state_ != Num::kInt) return fail(TapeError::kMalformedNumber, offset);
  num_state_ = Num::kFrac;
}

void GoldenTapeDecoder::start_word(Word w, uint32_t offset) {
  word_ = w;
  num_state_ = Num::kStart;
  num_ = 0;
  neg_ = false;
  frac_count_ = 0;
  word_offset_ = offset;
}

// The word an address letter starts (kNone: not an address letter).
GoldenTapeDecoder::Word GoldenTapeDecoder::letter_word(char c) {
  switch (c) {
    case 'N': return Word::kN;
    case 'G': return Word::kG;
    case 'M': return Word::kM;
    case 'X': return Word::kX;
    case 'Y': return Word::kY;
    case 'I': return Word::kI;
    case 'J': return Word::kJ;
    case 'F': return Word::kF;
    default: return Word::kNone;
  }
}

// The word being read has its whole number (all its fraction digits).
bool GoldenTapeDecoder::word_complete() const {
  const bool fractional = word_ != Word::kN && word_ != Word::kG && word_ != Word::kM;
  return fractional ? num_state_ == Num::kFrac && frac_count_ == fraction_digits(word_)
                    : num_state_ == Num::kInt;
}

// ---------------------------------------------------------------------------------------
// Block assembly and error capture (rtl/tape_decoder.sv).

void GoldenTapeDecoder::body_character(char c, uint32_t offset) {
  if (c == ' ' || c == '\r') return;
  if (c >= '0' && c <= '9') return digit(static_cast<unsigned>(c - '0'), offset);
  if (c == '+' || c == '-') return sign(c == '-', offset);
  if (c == '.') return dot(offset);
  // Any other character ends the word being read; the word is checked first.
  if (word_ != Word::kNone && !end_word()) return;
  const Word w = letter_word(c);
  if (w != Word::kNone) {
    if (w == Word::kN) {
      if (n_seen_) return fail(TapeError::kMissingEndOfBlock, offset);  // the LF is missing
      n_seen_ = true;
    }
    any_word_ = true;
    return start_word(w, offset);
  }
  switch (c) {
    case '\n': return end_of_block(offset);
    case '(': state_ = State::kComment; return;
    case '%':
      return fail(any_word_ ? TapeError::kMissingEndOfBlock : TapeError::kTruncatedTape,
                  offset);
    default: return fail(TapeError::kUnknownCharacter, offset);
  }
}

// The word being read ends: the parser checks it is complete, then its value is committed
// to the block. False after raising an error.
bool GoldenTapeDecoder::end_word() {
  const Word w = word_;
  const bool complete = word_complete();
  word_ = Word::kNone;
  if (!complete) {
    fail(TapeError::kMalformedNumber, word_offset_);
    return false;
  }
  return commit_word(w);
}

// Gives the word its meaning in the block; false after raising an error (an unsupported G
// or M code, at the word's letter).
bool GoldenTapeDecoder::commit_word(Word w) {
  const uint32_t value32 = static_cast<uint32_t>(num_);
  switch (w) {
    case Word::kN: block_.n = value32; break;
    case Word::kG:
      if (tape::is_motion(num_)) {
        block_.motion = static_cast<uint8_t>(num_);  // the G number is the motion code
        // Without circle mode an arc's G word is refused where it stands.
        if (!circle_mode_ && block_.is_arc()) {
          fail(TapeError::kNoCircleMode, word_offset_);
          return false;
        }
        motion_block_ = true;
      } else if (tape::code_kind('G', num_) != tape::CodeKind::kSetting) {
        fail(TapeError::kUnsupportedCode, word_offset_);
        return false;
      }
      break;
    case Word::kM: {
      // One M word per block: each acts at its own point of the block.
      const bool m_seen = end_block_ || block_.stop || block_.optional_stop || block_.tool_on ||
                          block_.tool_off;
      const tape::CodeKind kind = tape::code_kind('M', num_);
      const bool acts = !m_seen && misc_functions_;  // M00, M01, M03, M05 are played
      if (!m_seen && kind == tape::CodeKind::kEnd) end_block_ = true;
      else if (acts && kind == tape::CodeKind::kStop) block_.stop = true;
      else if (acts && kind == tape::CodeKind::kOptionalStop) block_.optional_stop = true;
      else if (acts && kind == tape::CodeKind::kToolOn) block_.tool_on = true;
      else if (acts && kind == tape::CodeKind::kToolOff) block_.tool_off = true;
      else {
        fail(TapeError::kUnsupportedCode, word_offset_);
        return false;
      }
      break;
    }
    case Word::kX: block_.dx = value32; block_.dx_neg = neg_; motion_block_ = true; break;
    case Word::kY: block_.dy = value32; block_.dy_neg = neg_; motion_block_ = true; break;
    case Word::kI: block_.i = value32; block_.i_neg = neg_; motion_block_ = true; break;
    case Word::kJ: block_.j = value32; block_.j_neg = neg_; motion_block_ = true; break;
    case Word::kF: block_.feed = num_; break;
    case Word::kNone: break;
  }
  return true;
}

void GoldenTapeDecoder::end_of_block(uint32_t offset) {
  const bool action = block_.stop || block_.optional_stop || block_.tool_on || block_.tool_off;
  if (motion_block_ || action) {
    if (motion_block_ && block_.feed == 0 && !block_.is_rapid())
      return fail(TapeError::kMissingFeed, offset);
    // Prepared first (cleared at the handoff): S starts at 0; a line adds F, then doubles
    // it k times (k = bit length of max(|dx|, |dy|)); a rapid traverse, or a still block,
    // adds the rapid step once, its S whatever its length.
    const uint32_t d = block_.dx | block_.dy;
    shifts_ = prepared_rapid() ? 0u : bit_length(d);
    block_.step = 0;
    block_.step_over = false;
    block_.iterations = 0;
    feed_in_ = !prepared_arc();
    state_ = State::kPrepare;
    return;
  }
  if (end_block_) state_ = State::kEnd;
  clear_block();
}

void GoldenTapeDecoder::add_to_step(uint64_t addend, bool addend_over) {
  // The RTL's one adder on StepWidth bits: the sum's low bits, and the carry out (or an
  // addend that does not fit) sets the over flag for good. step, addend <= step_mask_ <
  // 2^63: no overflow here.
  const uint64_t sum = block_.step + (addend & step_mask_);
  block_.step_over = block_.step_over || sum > step_mask_ || addend_over;
  block_.step = sum & step_mask_;
}

void GoldenTapeDecoder::prepare_edge() {
  if (!prepared_arc()) {  // a line: S = F << k: F at the first clock, then one doubling per
                          // clock; a rapid traverse (or a still block): the rapid step
    if (feed_in_) {
      const uint64_t f = prepared_rapid() ? rapid_step_ : block_.feed;
      add_to_step(f, f > step_mask_);
      block_.iterations = uint64_t{1} << bit_length(block_.dx | block_.dy);  // with k
      feed_in_ = false;
    } else if (shifts_ == 0) {
      state_ = State::kHold;
    } else {
      add_to_step(block_.step, false);
      --shifts_;
    }
    return;
  }
  const ArcPrepare::Result r = arc_.edge(block_.arc_words());
  if (r.iterate) {  // F once per dry-run iteration: S = F * N
    add_to_step(block_.feed, block_.feed > step_mask_);
    ++block_.iterations;
  }
  if (!r.done) return;
  if (r.error != TapeError::kNone) {
    fail(r.error, (frame_count_ - 1) & offset_mask_);  // the block's LF, the last frame read
  } else {
    state_ = State::kHold;
  }
}

void GoldenTapeDecoder::handoff() {
  state_ = end_block_ ? State::kEnd : State::kBody;
  clear_block();
}

void GoldenTapeDecoder::clear_block() {
  n_seen_ = any_word_ = motion_block_ = end_block_ = false;
  block_.stop = block_.optional_stop = block_.tool_on = block_.tool_off = false;
  block_.dx = block_.dy = block_.i = block_.j = 0;
  block_.dx_neg = block_.dy_neg = block_.i_neg = block_.j_neg = false;
}

void GoldenTapeDecoder::fail(TapeError code, uint32_t offset) {
  err_code_ = code;
  err_block_ = block_.n;
  err_offset_ = offset;
  state_ = State::kError;
}

}  // namespace ncinterp
