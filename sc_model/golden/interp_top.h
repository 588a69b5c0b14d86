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
  inline void tick(const InterpInputs& in);

  // Event jumping (used by `ncinterp check`; docs/verification.md 7). quiet_ticks(in): how
  // many of the next edges, with `in` held, change nothing but the feed phase and the cycle
  // count (the outputs stay as they are): 0 when the next edge does more (a strobe, a
  // pulse to clear, a load, the decoder, a status, the fault hook). skip(n), n <= that
  // count, leaves exactly the state of n calls of tick(in). Cosim and play tick every clock.
  uint64_t quiet_ticks(const InterpInputs& in) const;
  void skip(uint64_t n);

  const InterpOutputs& outputs() const { return out_; }
  const InterpConfig& config() const { return cfg_; }
  uint64_t cycle() const { return cycle_; }
  // Motion blocks loaded into the player since reset (for statistics and monitors).
  uint64_t blocks_loaded() const { return loads_; }
  // The feed generator's rate u (with ramps; S for a block without).
  uint64_t rate() const { return accel_step_ > 0 ? rate_ : feed_step_; }

  void inject(const Fault& fault);

 private:
  inline void player_edge(bool strobe);  // the player's DDA at an edge of a playing block
  inline void ramp_edge();               // the rate u for the next clock
  // The override register and its multiplier at an edge (`load`: a block loaded at it).
  void multiplier_edge(const InterpInputs& in, bool load);
  // The playing block's override P (override_q), from its rapid flag.
  uint16_t override_input(const InterpInputs& in) const {
    return (rapid_ ? in.rapid_override : in.feed_override) & ((1u << kOverrideWidth) - 1);
  }
  // held_, or (with the ramp) the override at 0: the target is 0, no start from rest.
  bool halted() const { return held_ || override_ == 0; }
  // The ramp's target u moves toward (feed_generator.sv's target).
  uint64_t ramp_target() const {
    return halted()                    ? 0
           : override_ == kOverrideOne ? rate_base_
           : mul_left_ > 0             ? rate_
                                       : product_;
  }
  void load_block();           // block buffer -> player
  void frame_edge(const InterpInputs& in, bool buffer_empty);  // decoder and buffer
  void status_edge();                       // done / error when the player is empty
  void stop_edge(const InterpInputs& in);   // a stop input latches
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
  // Block buffer ("next" register). In the serial arch it is a block RAM whose registered read
  // shows the last block taken, or the playing block's slot while the player reads that
  // block's words (SerialDda::words()): a block is readable (next_readable()) when the
  // player holds no words and the read register has had a clock to fetch it, after the
  // take (next_taken_cycle_) and after the hold (words_end_cycle_). Cycle numbers, not
  // flags cleared every tick: the hot path stores nothing for them.
  DecodedBlock next_;
  bool next_valid_ = false;
  uint64_t next_taken_cycle_ = 0, words_end_cycle_ = 0;
  bool next_readable() const {
    return !cfg_.serial() || (!serial_.words() && cycle_ != next_taken_cycle_ + 1 &&
                                cycle_ != words_end_cycle_ + 1);
  }
  // Player: feed generator and the DDA (lines and arcs). The feed generator's lead
  // (serial arch: the serial DDA's iteration takes 2^lead_bits_ clocks): the phase starts
  // at S << lead_bits_, and a block is saturated from S >= saturation_step_ (S << lead_bits_
  // >= M).
  unsigned lead_bits_ = 0;
  uint64_t saturation_step_ = 0;
  uint64_t feed_step_ = 0;  // S = F * N
  uint64_t phase_ = 0;
  bool saturated_ = false;
  // The ramp (accel_step_ > 0, docs/motion-control.md): the phase grows by rate_ (u, a
  // multiple of du = accel_step_ from 0), which moves by at most du per clock toward its
  // target (ramp_target()): rate_base_, the block's S capped at rate_cap_ (u < M / 2 and
  // u 2^lead_bits_ < M: at most one strobe in 2 clocks, or per serial iteration), at an
  // override P of 100 %; at another P (override_, the feed override, or for a rapid_ block
  // the rapid override, in units of 1 / kOverrideOne) product_, rate_base_ P capped again,
  // which feed_generator.sv's shift-and-add multiplier has mul_left_ edges after its
  // restart (a load, a change of P), the target being u meanwhile. slack_: K, the phase
  // units to the block's last strobe (N M at the load, less each clock's u) less what a
  // stop from u adds, B(u) = u + (u - du) + ... + du. K stays above -du in a block
  // (ramp_edge() brakes in time), so the block ends at u <= du.
  uint64_t accel_step_ = 0, rate_cap_ = 0;
  uint64_t rate_ = 0, rate_base_ = 0, product_ = 0;
  bool rapid_ = false;
  uint16_t override_ = kOverrideOne;
  unsigned mul_left_ = 0;
  __int128 slack_ = 0;
  // Feed hold (hold_i until start_i): no strobe without ramps; with them, the target 0.
  bool held_ = false;
  // The stop that stopped the machine (interp_top's stop_q): 0 none, 1 E-stop, 2 X limit,
  // 3 Y limit. Stopped, no block loads and no iteration starts.
  uint8_t stop_ = 0;
  // The playing block's M word that acts after its motion (interp_top.sv's after_*_q,
  // latched at its load): M05, M00, M01. The tool and the pause are out_.tool and
  // out_.paused.
  bool after_tool_off_ = false, after_stop_ = false, after_optional_stop_ = false;
  bool dir_[2] = {false, false};
  // The player's DDA: CircleDda, or in the serial arch SerialDda. player_done_ and
  // player_running_ are its done() and (SerialDda) an iteration's passes running, kept
  // here so that a clock without an iteration reads two flags (asking the DDAs instead,
  // behind an arch branch, made sim_bench's golden row 13 % slower).
  CircleDda circle_;
  SerialDda serial_;
  bool player_done_ = true, player_running_ = false;
  CircleDda& player_dda() { return cfg_.serial() ? serial_.dda() : circle_; }
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

inline void GoldenInterp::tick(const InterpInputs& in) {
  ++cycle_;
  // Every decision below reads the registers as they were before this edge (the _q
  // values): they are taken first, then the player, the buffer and the decoder update.
  using State = GoldenTapeDecoder::State;
  const bool busy = out_.busy;
  const bool finishing = busy && player_done_;
  const bool buffer_empty = !next_valid_;
  const State dstate = decoder_.state();
  // A stop input latches while the program runs (a stop has raised error already).
  const bool stop_now = (in.estop || in.limit_x || in.limit_y) && !out_.done && !out_.error;
  const bool stopped = stop_ != 0;
  const bool paused = out_.paused;
  if (!busy && buffer_empty && !paused && (dstate == State::kError || dstate == State::kEnd))
    status_edge();
  // The playing block ends with a pause (M00, or M01 with the switch on): none loads.
  const bool pause =
      finishing && (after_stop_ || (after_optional_stop_ && in.optional_stop));
  const bool load = !buffer_empty && (!busy || (finishing && !pause)) && next_readable() &&
                    !stopped && !paused;
  // The M words act only at a block's end or load, or while paused (and the end of the
  // program or an error clears them, below); most edges skip them. The tool: off after an
  // M05 block's motion, on at an M03 block's load (which wins); read before load_block()
  // latches the next block's words.
  const bool m_edge = finishing || load || paused;
  bool tool = out_.tool;
  if (m_edge) tool = (tool && !(finishing && after_tool_off_)) || (load && next_.tool_on);

  out_.step_x = false;
  out_.step_y = false;
  if (busy && !finishing) {
    // Feed generator (rtl/feed_generator.sv): one DDA iteration per strobe; with ramps the
    // phase grows by the rate u, which ramp_edge() moves toward the block's S.
    bool strobe = false;
    if (stopped) {
      // A stop input has stopped the machine: no strobe; a serial iteration in flight ends
      // without its pulses (player_edge()).
    } else if (accel_step_ == 0) {
      strobe = saturated_ && !held_;
      if (!strobe && !held_) {
        const uint64_t p = phase_ + feed_step_;
        strobe = p >= modulus_;
        phase_ = strobe ? p - modulus_ : p;
      }
    } else {
      const uint64_t p = phase_ + rate_;
      strobe = p >= modulus_;
      phase_ = strobe ? p - modulus_ : p;
      ramp_edge();  // after reading u: the next clock's rate
    }
    if (strobe || player_running_) player_edge(strobe);
  } else if (finishing && !load) {
    out_.busy = false;
    out_.feed_saturated = false;
  }
  if (load) load_block();  // Block buffer (rtl/block_buffer.sv) -> player
  if (!decoder_.quiet(in, buffer_empty)) frame_edge(in, buffer_empty);
  if (cycle_ == fault_cycle_) fault_edge();
  held_ = in.hold || (held_ && !in.start);
  if (accel_step_ > 0 && (mul_left_ > 0 || load || override_input(in) != override_))
    multiplier_edge(in, load);
  if (stop_now) stop_edge(in);
  // The pause until cycle start, and the tool, end with the program (a stop, an error, or
  // its end).
  if (m_edge || out_.error || out_.done) {
    out_.paused = (pause || (paused && !in.start)) && !out_.error;
    out_.tool = tool && !out_.error && !out_.done;
  }
}

// The ramp's decision for the next clock (rtl/feed_generator.sv decides the same), from the
// slack K before this clock's add of u: up by du if K > 2u + du, i.e. after this clock's u
// the slack still covers B(u + du) - B(u) = u + du, so a stop from u + du still ends before
// the block's last strobe; from rest whenever the block
// has phase left (K > 0), whatever the target, so a block never waits (not even one that a
// hold stopped just before its end); else stay if K > u (a stop from u still fits) and u
// is not above its target, or creep at u = du while the block has phase left; else down by
// du, which leaves K as it is (B(u - du) = B(u) - u). The compares are strict, as the
// hardware's are (it keeps K as whole iterations and a fraction).
// Halted (held, or the override at 0), the target is 0 and neither the start from rest nor
// the creep applies: u ramps down to 0 and stays there, and the phase stops.
inline void GoldenInterp::ramp_edge() {
  const bool halt = halted();
  const uint64_t u = rate_, du = accel_step_, target = ramp_target();
  const __int128 w = static_cast<__int128>(u), up = 2 * w + static_cast<__int128>(du);
  if (u == 0 && !halt ? slack_ > 0 : u + du <= target && slack_ > up) {
    rate_ = u + du;
    slack_ -= up;
  } else if ((u <= target && slack_ > w) || (u == du && !halt && slack_ > 0)) {
    slack_ -= w;
  } else if (u > 0) {
    rate_ = u - du;
  }
}

// CircleDda iterates at a strobe; SerialDda (docs/interpolator.md 5.6) starts an iteration
// at a strobe and plays it over 2P clocks, reading the block's words from the buffer in its
// first pass (dda_serial.sv's mute_i: once stopped, its pulses are not emitted).
inline void GoldenInterp::player_edge(bool strobe) {
  CircleDda::Steps s;
  if (cfg_.serial()) {
    const bool words = serial_.words();
    const SerialDda::Edge e = serial_.edge(strobe);
    s = {e.x && stop_ == 0, e.y && stop_ == 0};  // stopped: the iteration in flight is mute
    player_running_ = serial_.running();
    player_done_ = serial_.done();
    if (words && !serial_.words()) words_end_cycle_ = cycle_;
  } else {
    s = circle_.iterate();
    player_done_ = circle_.done();
  }
  // Position counters (rtl/position_counter.sv).
  if (s.x) out_.pos_x = wrap_position(out_.pos_x + (dir_[0] ? 1 : -1));
  if (s.y) out_.pos_y = wrap_position(out_.pos_y + (dir_[1] ? 1 : -1));
  out_.step_x = s.x;
  out_.step_y = s.y;
}

}  // namespace ncinterp
