// Tape decoder of the golden model: the C++ twin of rtl/tape_decoder.sv and its two parts.
// Idea: frames -> words -> one decoded motion block at a time, with the same registers and
// the same next-state rules as the RTL (docs/interpolator.md, section 3). The members and
// tape_decoder.cpp come in the RTL's three sections: "Frame input" (rtl/tape_frame_input.sv:
// input register, parity, offset), "Word parser" (rtl/tape_word_parser.sv: number syntax
// and limits) and "Block assembly and error capture" (rtl/tape_decoder.sv itself). An arc
// block is checked and dry-run by ArcPrepare (the twin of rtl/arc_prepare.sv) before it is
// held. edge() is called only on clocks where something happens (quiet() is false), so the
// decoder stays off the golden model's hot path.
#pragma once
#include <cstdint>

#include "arc_prepare.h"
#include "interp_ports.h"

namespace ncinterp {

// A decoded motion block as it moves from the decoder through the block buffer to the
// player. Magnitudes and signs, as on tape; motion 1/2/3 = G01/G02/G03.
struct DecodedBlock {
  uint32_t n = 0;
  uint8_t motion = 1;
  uint32_t dx = 0, dy = 0, i = 0, j = 0;
  bool dx_neg = false, dy_neg = false, i_neg = false, j_neg = false;
  uint64_t feed = 0;
  // The feed generator's step S = F * N (N iterations: 2^k for a line, the circle DDA's
  // count for an arc); summed while the block is prepared, final when it is held: its low
  // bits, modulo 2^StepWidth (GoldenTapeDecoder::step_mask()), and whether it reached
  // 2^StepWidth (step_over: the block is saturated whatever the rest).
  uint64_t step = 0;
  bool step_over = false;
  // N, the block's DDA iterations (2^k for a line, the dry run's count for an arc): the
  // feed generator's ramp (GoldenInterp, docs/motion-control.md) brakes within them.
  uint64_t iterations = 0;
  // The block's M word that acts (block_record.def; at most one): M00, M01, M03, M05.
  bool stop = false, optional_stop = false, tool_on = false, tool_off = false;

  bool is_arc() const { return tape::is_arc(static_cast<tape::Motion>(motion)); }
  bool is_rapid() const { return motion == static_cast<uint8_t>(tape::Motion::kRapid); }
  ArcWords arc_words() const {
    return ArcWords{dx, dy, i, j, dx_neg, dy_neg, i_neg, j_neg, motion == 3};
  }
};

class GoldenTapeDecoder {
 public:
  // Order matters: the states up to kComment watch tape_end (truncated tape).
  enum class State : uint8_t { kLeader, kBody, kComment, kHold, kPrepare, kEnd, kError };

  explicit GoldenTapeDecoder(const InterpConfig& cfg);

  void reset();
  // Nothing would change at this edge: tape_end unchanged and, holding a block, the buffer
  // full and no frame taken (a waiting frame stays waiting); otherwise no frame offered or
  // waiting, no block being prepared, and the tape not ending early. Most clocks of a line
  // program are spent holding the next block while the buffer is full.
  bool quiet(const InterpInputs& in, bool buffer_empty) const {
    if (in.tape_end != tape_end_q_) return false;
    if (state_ == State::kHold) return !buffer_empty && !(in.frame_valid && ready_);
    return !in.frame_valid && !in_valid_ && state_ != State::kPrepare && digit_pass_ == 0 &&
           !(tape_end_q_ && state_ <= State::kComment);
  }
  // One rising edge. buffer_empty: the block buffer can take a held block at this edge
  // (the caller copies block() into the buffer first).
  void edge(const InterpInputs& in, bool buffer_empty);

  // S is kept in interp_top.sv's StepWidth = min(FeedWidth + W + 1, ModulusWidth -
  // LeadBits + 1) bits, plus a flag for S >= 2^StepWidth: beyond M >> LeadBits every S
  // saturates the block. This is 2^StepWidth - 1.
  static uint64_t step_mask(const InterpConfig& cfg);
  State state() const { return state_; }
  bool ready() const { return ready_; }
  bool tape_ended() const { return tape_end_q_; }
  // The held block as handed over: a still block (an M word, no motion word) is a G00.
  DecodedBlock block() const {
    DecodedBlock b = block_;
    if (!motion_block_) b.motion = static_cast<uint8_t>(tape::Motion::kRapid);
    return b;
  }
  TapeError error_code() const { return err_code_; }
  uint32_t error_block() const { return err_block_; }
  uint32_t error_offset() const { return err_offset_; }

 private:
  enum class Word : uint8_t { kNone, kN, kG, kM, kX, kY, kI, kJ, kF };
  enum class Num : uint8_t { kStart, kSigned, kInt, kFrac };

  // Frame input.
  void process_frame(uint8_t frame);
  // Word parser.
  void digit(unsigned d, uint32_t offset);
  void sign(bool negative, uint32_t offset);
  void dot(uint32_t offset);
  static Word letter_word(char c);
  void start_word(Word w, uint32_t offset);
  bool word_complete() const;
  uint64_t limit(Word w) const;
  unsigned fraction_digits(Word w) const;
  // Block assembly and error capture.
  void body_character(char c, uint32_t offset);
  bool end_word();
  bool commit_word(Word w);
  void end_of_block(uint32_t offset);
  void prepare_edge();
  // The block being prepared plays as a traverse (a G00, or a still block), or an arc.
  bool prepared_rapid() const { return block_.is_rapid() || !motion_block_; }
  bool prepared_arc() const { return motion_block_ && block_.is_arc(); }
  void add_to_step(uint64_t addend, bool addend_over);
  void handoff();
  void clear_block();
  void fail(TapeError code, uint32_t offset);

  // Parameters. bit_serial_: a digit's x10 + d is a pass of num_width_ clocks (the RTL's
  // BitSerial; num_width_ is its NumWidth, the widest word register, at least 7 bits).
  // circle_mode_: G02/G03 are played (else refused: the RTL's CircleMode).
  bool bit_serial_;
  bool circle_mode_;
  bool misc_functions_;  // M00, M01, M03, M05 are played (else refused: MiscFunctions)
  unsigned num_width_;
  unsigned frac_digits_, feed_frac_digits_;
  uint64_t inc_limit_, feed_limit_, seq_limit_;
  uint32_t offset_mask_;
  uint64_t step_mask_;  // step_mask()
  uint64_t rapid_step_;  // rapid_step_i: a G00 block's S

  // Block assembly: the decoder's state.
  State state_ = State::kLeader;
  // Frame input. Input register: a frame taken from the reader, processed at the next edge.
  uint8_t in_frame_ = 0;
  bool in_valid_ = false;
  bool tape_end_q_ = false;  // tape_end one clock late
  bool ready_ = true;        // frame_ready (a register)
  uint32_t frame_count_ = 0;  // offset of the next frame
  // Word parser: the word being read.
  Word word_ = Word::kNone;
  Num num_state_ = Num::kStart;
  uint64_t num_ = 0;
  bool neg_ = false;
  unsigned frac_count_ = 0;
  uint32_t word_offset_ = 0;
  // BitSerial: the clocks left of a digit's pass (no frame is processed meanwhile), and
  // whether the number went over its word's limit (an error at the pass's last edge).
  unsigned digit_pass_ = 0;
  bool digit_over_ = false;
  // Block assembly (n, motion and feed are modal: never cleared at a block start; a still
  // block keeps the modal motion here, block() hands it over as a G00).
  DecodedBlock block_;
  bool n_seen_ = false, any_word_ = false, motion_block_ = false, end_block_ = false;
  // The block being prepared (kPrepare): a line's F still to add and doublings still to do
  // (the RTL's feed_in_q and shifts_q; S is block_.step), and an arc's checks and dry run.
  bool feed_in_ = false;
  unsigned shifts_ = 0;
  ArcPrepare arc_;
  // Error capture.
  TapeError err_code_ = TapeError::kNone;
  uint32_t err_block_ = 0;
  uint32_t err_offset_ = 0;
};

}  // namespace ncinterp
