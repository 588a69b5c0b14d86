// Golden cycle model of the interpolator: the C++ twin of rtl/interp_top.sv. Twins of the
// submodules: GoldenTapeDecoder (rtl/tape_decoder.sv), CircleDda (rtl/dda_circle.sv, which
// plays lines and arcs) or with BitSerial SerialDda (rtl/dda_serial.sv); the small ones are
// sections of tick() named after them: "Block buffer" (block_buffer.sv), "Feed generator"
// (feed_generator.sv), "Position counters" (position_counter.sv).
// Idea: one tick() is one rising clock edge. Every register of the RTL exists here with the
// same reset value and next-state rule (docs/interpolator.md), so after each tick the
// outputs equal the RTL's outputs after the same edge; the cosim checks this every clock.
// The model must be fast (>= 100 M cycles/s): the hot path is inline, a clock with no frame
// and no DDA iteration only advances the feed phase; the output struct is the output
// registers themselves; the fault hook costs one compare per tick.
#pragma once
#include <cstdint>
#include <limits>

#include "dda_circle.h"
#include "dda_serial.h"
#include "tape_decoder.h"
#include "interp_ports.h"

namespace ncinterp {

class GoldenInterp {
 public:
  // Test hook: one fault at a time, injected into the golden model only, so the lock-step
  // scoreboard (and the system monitors) can be shown to catch it. Semantics in
  // docs/interpolator.md section 9; cycle 1 is the first tick after reset().
  struct Fault {
    enum Kind { kNone, kLostPulse, kStuckStep, kAccumulatorOffByOne, kWrongDirection };
    Kind kind = kNone;
    uint64_t cycle = 0;
    int axis = 0;  // 0 = X, 1 = Y
  };

  explicit GoldenInterp(const InterpConfig& cfg);

  // State after an edge with rst_ni = 0; clears the cycle counter (not an injected fault).
  void reset();

  // One rising clock edge with these inputs.
  inline void tick(const InterpInputs& in) {
    if (cfg_.bit_serial)
      tick_bit_serial(in);
    else
      tick_parallel(in);
  }

  const InterpOutputs& outputs() const { return out_; }
  const InterpConfig& config() const { return cfg_; }
  uint64_t cycle() const { return cycle_; }
  // Motion blocks loaded into the player since reset (for statistics and monitors).
  uint64_t blocks_loaded() const { return loads_; }

  void inject(const Fault& fault);

 private:
  inline void tick_parallel(const InterpInputs& in);    // the player on CircleDda
  inline void tick_bit_serial(const InterpInputs& in);  // the player on SerialDda
  void load_block();           // block buffer -> player
  void frame_edge(const InterpInputs& in, bool buffer_empty);  // decoder and buffer
  void status_edge();                       // done / error when the player is empty
  void fault_edge();           // the injected fault acts at this cycle
  int64_t wrap_position(int64_t p) const {
    const uint64_t u = static_cast<uint64_t>(p) & pos_mask_;
    return static_cast<int64_t>((u ^ pos_sign_) - pos_sign_);  // sign-extend
  }

  InterpConfig cfg_;
  // feed_modulus_i, ModulusWidth bits. The RTL registers it (modulus_q), which equals this
  // constant from the first clock on; no block can load before the fourth clock.
  uint64_t modulus_;
  uint64_t pos_mask_, pos_sign_;

  GoldenTapeDecoder decoder_;
  // Block buffer ("next" register). With bit_serial it is a block RAM of two slots whose
  // registered read shows one slot: the last one written (slot_), but the playing block's
  // while the player still reads its words (SerialDda::words()); shown_ is the slot the
  // read register holds, and a block can load only once it is shown (block_buffer.sv).
  DecodedBlock next_;
  bool next_valid_ = false;
  bool slot_ = false, shown_ = false;
  // Player: feed generator and the DDA (lines and arcs). The feed generator's lead
  // (bit_serial: the serial DDA's iteration takes 2^lead_bits_ clocks): the phase starts
  // at S << lead_bits_, and a block is saturated from S >= saturation_step_ (S << lead_bits_
  // >= M).
  unsigned lead_bits_ = 0;
  uint64_t saturation_step_ = 0;
  uint64_t feed_step_ = 0;  // S = F * N
  uint64_t phase_ = 0;
  bool saturated_ = false;
  bool dir_[2] = {false, false};
  CircleDda circle_;   // the player's DDA, or with bit_serial:
  SerialDda serial_;
  CircleDda& player_dda() { return cfg_.bit_serial ? serial_.dda() : circle_; }
  // Outputs: the output registers themselves.
  InterpOutputs out_;

  uint64_t cycle_ = 0;
  uint64_t loads_ = 0;  // blocks loaded since reset (the fault hook's notion of "block")
  // Fault hook: fault_edge() runs when cycle_ == fault_cycle_; an active fault re-arms it
  // for the next cycle.
  Fault fault_;
  uint64_t fault_cycle_ = std::numeric_limits<uint64_t>::max();
  bool fault_active_ = false;
  uint64_t fault_block_ = 0;
};

inline void GoldenInterp::tick_parallel(const InterpInputs& in) {
  ++cycle_;
  // Every decision below reads the registers as they were before this edge (the _q
  // values): they are taken first, then the player, the buffer and the decoder update.
  using State = GoldenTapeDecoder::State;
  const bool busy = out_.busy;
  const bool finishing = busy && circle_.done();
  const bool buffer_empty = !next_valid_;
  const State dstate = decoder_.state();
  if (!busy && buffer_empty && (dstate == State::kError || dstate == State::kEnd))
    status_edge();
  const bool load = !buffer_empty && (!busy || finishing);

  out_.step_x = false;
  out_.step_y = false;
  if (busy && !finishing) {
    // Feed generator (rtl/feed_generator.sv): one DDA iteration per strobe.
    bool strobe = saturated_;
    if (!strobe) {
      const uint64_t p = phase_ + feed_step_;
      strobe = p >= modulus_;
      phase_ = strobe ? p - modulus_ : p;
    }
    if (strobe) {
      const CircleDda::Steps s = circle_.iterate();
      const bool carry[2] = {s.x, s.y};
      // Position counters (rtl/position_counter.sv).
      if (carry[0]) out_.pos_x = wrap_position(out_.pos_x + (dir_[0] ? 1 : -1));
      if (carry[1]) out_.pos_y = wrap_position(out_.pos_y + (dir_[1] ? 1 : -1));
      out_.step_x = carry[0];
      out_.step_y = carry[1];
    }
  } else if (finishing && !load) {
    out_.busy = false;
    out_.feed_saturated = false;
  }
  if (load) load_block();  // Block buffer (rtl/block_buffer.sv) -> player
  if (!decoder_.quiet(in, buffer_empty)) frame_edge(in, buffer_empty);
  if (cycle_ == fault_cycle_) fault_edge();
}

// The same with the bit-serial player (docs/interpolator.md 5.5): the DDA takes 2P clocks
// per iteration and reads a block's words from the buffer in its first pass.
inline void GoldenInterp::tick_bit_serial(const InterpInputs& in) {
  ++cycle_;
  using State = GoldenTapeDecoder::State;
  const bool busy = out_.busy;
  const bool finishing = busy && serial_.done();
  const bool buffer_empty = !next_valid_;
  const bool holding = serial_.words();
  const State dstate = decoder_.state();
  if (!busy && buffer_empty && (dstate == State::kError || dstate == State::kEnd))
    status_edge();
  // Block buffer: a block is readable once its slot is shown and the player holds none.
  const bool load = !buffer_empty && !holding && shown_ == slot_ && (!busy || finishing);
  shown_ = slot_ != (holding && !buffer_empty);

  out_.step_x = false;
  out_.step_y = false;
  if (busy && !finishing) {
    // Feed generator: a strobe always finds the DDA idle unless the block is saturated.
    bool strobe = saturated_;
    if (!strobe) {
      const uint64_t p = phase_ + feed_step_;
      strobe = p >= modulus_;
      phase_ = strobe ? p - modulus_ : p;
    }
    const SerialDda::Edge e = serial_.edge(strobe);
    if (e.x) out_.pos_x = wrap_position(out_.pos_x + (dir_[0] ? 1 : -1));
    if (e.y) out_.pos_y = wrap_position(out_.pos_y + (dir_[1] ? 1 : -1));
    out_.step_x = e.x;
    out_.step_y = e.y;
  } else if (finishing && !load) {
    out_.busy = false;
    out_.feed_saturated = false;
  }
  if (load) load_block();
  if (!decoder_.quiet(in, buffer_empty)) frame_edge(in, buffer_empty);
  if (cycle_ == fault_cycle_) fault_edge();
}

}  // namespace ncinterp
