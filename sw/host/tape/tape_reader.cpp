// Tape reader: frames -> Program, enforcing every rule of the hardware tape decoder.
// Idea: a frame-by-frame state machine over the same states as the decoder
// (docs/interpolator.md section 3: LEADER, BODY, COMMENT, END), with the same priorities
// inside one frame (parity, then the word the frame ends, then the frame's own character)
// and the same error codes, blocks and offsets; arc blocks are checked at their LF like the
// decoder's arc preparation does (docs/circle-dda.md section 2). Written independently of
// the golden decoder (sc_model/golden/tape_decoder.cpp, arc_geometry.cpp); tests/sw/host/tape
// cross-checks the two on thousands of damaged tapes, so a tape this reader accepts is a
// tape the machine plays.
#include <cstdio>
#include <stdexcept>
#include <string>

#include "arc_rules.h"
#include "tape.h"

namespace ncinterp::tape {

namespace {

uint64_t max_for_width(unsigned bits) { return bits >= 64 ? ~0ull : (1ull << bits) - 1; }

std::string printable(uint8_t frame) {
  const unsigned c = frame & 0x7f;
  char buf[32];
  if (c >= 0x21 && c < 0x7f)
    std::snprintf(buf, sizeof buf, "'%c' (frame 0x%02X)", static_cast<char>(c), frame);
  else
    std::snprintf(buf, sizeof buf, "frame 0x%02X", frame);
  return buf;
}

// Thrown inside the reader on the first error; run() turns it into the result.
struct Stop {
  TapeErrorInfo info;
};

class Reader {
 public:
  explicit Reader(const Format& f)
      : format_(f),
        inc_max_(max_for_width(f.inc_width)),
        feed_max_(max_for_width(f.feed_width)),
        seq_max_(max_for_width(f.seq_width)) {}

  ParseResult run(const std::vector<uint8_t>& frames) {
    ParseResult result;
    try {
      for (offset_ = 0; offset_ < frames.size(); ++offset_) frame(frames[offset_]);
      // Without a '%' every frame is leader: the program never started, whatever M02 the
      // leader holds.
      if (state_ == State::kLeader)
        fail(TapeError::kTruncatedTape, frames.size(),
             "truncated tape: no '%' starts the program, so all of it is leader");
      if (state_ != State::kEnd)
        fail(TapeError::kTruncatedTape, frames.size(), "truncated tape: it ends before M02/M30");
    } catch (const Stop& stop) {
      result.error = stop.info;
    }
    result.program = std::move(program_);
    return result;
  }

 private:
  enum class State { kLeader, kBody, kComment, kEnd };
  enum class Word { kNone, kN, kG, kM, kX, kY, kI, kJ, kF };
  enum class Part { kStart, kSign, kInteger, kFraction };  // how far the number has come

  [[noreturn]] void fail(TapeError code, uint64_t offset, std::string message) {
    throw Stop{TapeErrorInfo{n_, offset, std::move(message), static_cast<unsigned>(code)}};
  }

  void frame(uint8_t f) {
    if (!has_even_parity(f)) fail(TapeError::kParity, offset_, "parity error: " + printable(f));
    const char c = static_cast<char>(f & 0x7f);
    switch (state_) {
      case State::kLeader:  // everything before '%' is leader
        if (c == '%') state_ = State::kBody;
        break;
      case State::kComment:
        if (c == ')') state_ = State::kBody;
        break;
      case State::kEnd:
        if (!(c == '%' || c == '\0' || c == '\r' || c == '\n' || c == ' '))
          fail(TapeError::kBlockAfterEnd, offset_, "block after end of program: " + printable(f));
        break;
      case State::kBody:
        body(c, f);
        break;
    }
  }

  void body(char c, uint8_t f) {
    if (c == ' ' || c == '\r') return;  // ignored everywhere, even inside numbers
    if (c >= '0' && c <= '9') return digit(static_cast<unsigned>(c - '0'));
    if (c == '+' || c == '-') return sign(c == '-');
    if (c == '.') return point();
    if (word_ != Word::kNone) end_word();  // any other character ends the word first
    switch (c) {
      case 'N':
        if (n_in_block_)
          fail(TapeError::kMissingEndOfBlock, offset_,
               "missing end of block: a second N in one block");
        n_in_block_ = true;
        return begin_word(Word::kN, c);
      case 'G': return begin_word(Word::kG, c);
      case 'M': return begin_word(Word::kM, c);
      case 'X': return begin_word(Word::kX, c);
      case 'Y': return begin_word(Word::kY, c);
      case 'I': return begin_word(Word::kI, c);
      case 'J': return begin_word(Word::kJ, c);
      case 'F': return begin_word(Word::kF, c);
      case '\n': return end_block();
      case '(': state_ = State::kComment; return;
      case '%':
        if (block_has_word_)
          fail(TapeError::kMissingEndOfBlock, offset_, "missing end of block before '%'");
        fail(TapeError::kTruncatedTape, offset_, "truncated tape: '%' before M02/M30");
      default:
        fail(TapeError::kUnknownCharacter, offset_,
             "unknown address letter or character " + printable(f));
    }
  }

  bool signed_word() const {
    return word_ == Word::kX || word_ == Word::kY || word_ == Word::kI || word_ == Word::kJ;
  }
  unsigned fraction_digits() const {
    if (word_ == Word::kF) return format_.feed_frac_digits;
    return signed_word() ? format_.frac_digits : 0;
  }
  uint64_t max_value() const {
    switch (word_) {
      case Word::kN: return seq_max_;
      case Word::kG:
      case Word::kM: return 99;
      case Word::kF: return feed_max_;
      default: return inc_max_;
    }
  }
  std::string word_name() const { return std::string(1, letter_) + " word"; }

  void digit(unsigned d) {
    if (word_ == Word::kNone)
      fail(TapeError::kMalformedNumber, offset_,
           "malformed number: a digit without an address letter");
    if (part_ == Part::kFraction && fraction_count_ == fraction_digits())
      fail(TapeError::kMalformedNumber, offset_,
           "malformed number: " + word_name() + " has more than " +
               std::to_string(fraction_digits()) + " fraction digits");
    if (value_ > (max_value() - d) / 10)
      fail(TapeError::kValueTooWide, offset_, "value too wide for its register: " + word_name() +
                                       " exceeds " + std::to_string(max_value()));
    value_ = value_ * 10 + d;
    if (part_ == Part::kFraction)
      ++fraction_count_;
    else
      part_ = Part::kInteger;
  }

  void sign(bool negative) {
    if (word_ == Word::kNone || !signed_word() || part_ != Part::kStart)
      fail(TapeError::kMalformedNumber, offset_, "malformed number: misplaced sign");
    negative_ = negative;
    part_ = Part::kSign;
  }

  void point() {
    const bool fractional = signed_word() || word_ == Word::kF;
    if (!fractional || part_ != Part::kInteger)
      fail(TapeError::kMalformedNumber, offset_, "malformed number: misplaced '.'");
    part_ = Part::kFraction;
  }

  void begin_word(Word w, char letter) {
    block_has_word_ = true;
    word_ = w;
    letter_ = letter;
    word_offset_ = offset_;
    part_ = Part::kStart;
    value_ = 0;
    negative_ = false;
    fraction_count_ = 0;
  }

  // Checks the word that just ended and applies it to the block.
  void end_word() {
    const bool fractional = signed_word() || word_ == Word::kF;
    const bool complete = fractional
                              ? part_ == Part::kFraction && fraction_count_ == fraction_digits()
                              : part_ == Part::kInteger;
    if (!complete)
      fail(TapeError::kMalformedNumber, word_offset_,
           "malformed number: " + word_name() +
               (fractional ? " needs digits, '.' and exactly " +
                                 std::to_string(fraction_digits()) + " fraction digits"
                           : " needs digits"));
    const int64_t v = negative_ ? -static_cast<int64_t>(value_) : static_cast<int64_t>(value_);
    const Word w = word_;
    word_ = Word::kNone;
    switch (w) {
      case Word::kN: n_ = static_cast<uint32_t>(value_); break;
      case Word::kG: g_code(); break;
      case Word::kM: m_code(); break;
      case Word::kX: block_.dx = v; motion_in_block_ = true; break;
      case Word::kY: block_.dy = v; motion_in_block_ = true; break;
      case Word::kI: block_.i = v; motion_in_block_ = true; break;
      case Word::kJ: block_.j = v; motion_in_block_ = true; break;
      case Word::kF: feed_ = value_; break;
      case Word::kNone: break;
    }
  }

  void g_code() {
    switch (value_) {
#define TAPE_MOTION(name, code, word) \
  case code: motion_ = Motion::k##name; break;
#include "tape_motions.def"
#undef TAPE_MOTION
      default:
        if (code_kind('G', value_) != CodeKind::kSetting) unsupported("G");
        return;  // a setting: what the interpolator always does
    }
    if (!format_.circle_mode && is_arc(motion_))
      fail(TapeError::kNoCircleMode, word_offset_,
           "G0" + std::to_string(value_) + ": an arc block, but the interpolator is built without "
           "circle mode (lines only); write the arcs as chords (ncinterp tape --arcs chords)");
    motion_in_block_ = true;
  }

  // One M word per block: each acts at its own point of the block (tape_codes.def).
  void m_code() {
    if (m_in_block_)
      fail(TapeError::kUnsupportedCode, word_offset_,
           "unsupported G or M code: M" + std::to_string(value_) +
               " is a second M word in the block (one M word per block)");
    m_in_block_ = true;
    const CodeKind kind = code_kind('M', value_);
    if (kind == CodeKind::kEnd) {
      end_m30_ = value_ == 30;
      end_in_block_ = true;
      return;
    }
    if (kind == CodeKind::kUnsupported) unsupported("M");
    if (!format_.misc_functions)
      fail(TapeError::kUnsupportedCode, word_offset_,
           "unsupported G or M code: M" + std::to_string(value_) +
               ": the interpolator is built without M00, M01, M03 and M05 (the iCEstick's "
               "configuration, MiscFunctions = 0)");
    block_.stop = kind == CodeKind::kStop;
    block_.optional_stop = kind == CodeKind::kOptionalStop;
    block_.tool_on = kind == CodeKind::kToolOn;
    block_.tool_off = kind == CodeKind::kToolOff;
  }

  [[noreturn]] void unsupported(const char* letter) {
    fail(TapeError::kUnsupportedCode, word_offset_,
         std::string("unsupported G or M code: ") + letter + std::to_string(value_));
  }

  void end_block() {
    const bool action = block_.stop || block_.optional_stop || block_.tool_on || block_.tool_off;
    if (!motion_in_block_ && action) {
      // A still block: the M word's block, played as a G00 of length 0.
      block_.n = n_;
      block_.motion = Motion::kRapid;
      block_.still = true;
      program_.blocks.push_back(block_);
    } else if (motion_in_block_) {
      // A G00 block needs no F (it plays at the rapid rate): its feed is 0 in the Program,
      // while an F word in it still sets the modal F for the blocks that follow.
      const bool rapid = is_rapid(motion_);
      if (feed_ == 0 && !rapid)
        fail(TapeError::kMissingFeed, offset_,
             "missing feed: no F programmed (or F0) for a motion block");
      block_.n = n_;
      block_.motion = motion_;
      block_.feed = rapid ? 0 : feed_;
      if (is_arc(motion_)) check_arc();
      program_.blocks.push_back(block_);
    }
    if (end_in_block_) {
      program_.end_m30 = end_m30_;
      state_ = State::kEnd;
    }
    block_ = Block{};
    n_in_block_ = block_has_word_ = motion_in_block_ = end_in_block_ = m_in_block_ = false;
  }

  void check_arc() {
    const ArcRuleBroken broken = broken_arc_rule(block_, inc_max_);
    if (broken.code != TapeError::kNone) fail(broken.code, offset_, broken.message);
  }

  const Format& format_;
  const uint64_t inc_max_, feed_max_, seq_max_;
  State state_ = State::kLeader;
  uint64_t offset_ = 0;  // of the frame being read
  // The word being read.
  Word word_ = Word::kNone;
  char letter_ = ' ';
  uint64_t word_offset_ = 0;
  Part part_ = Part::kStart;
  uint64_t value_ = 0;  // digits read so far as one integer
  bool negative_ = false;
  unsigned fraction_count_ = 0;
  // Modal values (kept from block to block) and the block being assembled.
  uint32_t n_ = 0;  // the last N read
  Motion motion_ = Motion::kLine;
  uint64_t feed_ = 0;
  bool end_m30_ = false;
  Block block_;
  bool n_in_block_ = false, block_has_word_ = false, motion_in_block_ = false,
       end_in_block_ = false, m_in_block_ = false;
  Program program_;
};

}  // namespace

TapeFormatError::TapeFormatError(TapeErrorInfo info)
    : std::runtime_error(describe(info)), info_(std::move(info)) {}

std::string describe(const TapeErrorInfo& info) {
  return "block N" + std::to_string(info.block) + ", offset " + std::to_string(info.offset) +
         ": " + info.message;
}

ParseResult parse_frames_partial(const std::vector<uint8_t>& frames, const Format& format) {
  return Reader(format).run(frames);
}

Program parse_frames(const std::vector<uint8_t>& frames, const Format& format) {
  ParseResult result = parse_frames_partial(frames, format);
  if (result.error) throw TapeFormatError(*result.error);
  return std::move(result.program);
}

}  // namespace ncinterp::tape
