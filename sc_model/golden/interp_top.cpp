// Golden cycle model: the cold paths of GoldenInterp (block load, decoder and buffer
// activity, status, fault hook). The hot path, tick(), is inline in interp_top.h.
#include "interp_top.h"

#include "bit_length.h"

#include <algorithm>
#include <limits>
#include <stdexcept>
#include <string>

namespace ncinterp {

namespace {

uint64_t low_mask(unsigned bits) { return bits >= 64 ? ~0ull : (1ull << bits) - 1; }

void require(bool ok, const char* what) {
  if (!ok) throw std::invalid_argument(std::string("GoldenInterp: unsupported parameter: ") + what);
}

}  // namespace

GoldenInterp::GoldenInterp(const InterpConfig& cfg)
    : cfg_(cfg), decoder_(cfg), serial_(cfg.inc_width) {
  // The phase sum is formed only when not saturated (S < M < 2^62), so it cannot overflow.
  // |dx|, |dy| are held in 32 bits; S is kept below 2^63 (GoldenTapeDecoder::step_mask()).
  require(cfg.inc_width >= 1 && cfg.inc_width <= 32, "inc_width must be 1..32");
  require(cfg.feed_width >= 1 && cfg.feed_width + cfg.inc_width <= 64,
          "feed_width + inc_width must be <= 64");
  require(cfg.modulus_width >= 1 && cfg.modulus_width <= 62, "modulus_width must be 1..62");
  require(cfg.pos_width >= 2 && cfg.pos_width <= 63, "pos_width must be 2..63");
  require(cfg.seq_width >= 1 && cfg.seq_width <= 32, "seq_width must be 1..32");
  require(cfg.offset_width >= 1 && cfg.offset_width <= 32, "offset_width must be 1..32");
  require(cfg.frac_digits <= 9 && cfg.feed_frac_digits <= 9, "fraction digits must be <= 9");
  modulus_ = cfg.feed_modulus & low_mask(cfg.modulus_width);
  lead_bits_ = SerialDda::player_lead_bits(cfg);
  saturation_step_ = (modulus_ + (uint64_t{1} << lead_bits_) - 1) >> lead_bits_;
  accel_step_ = cfg.accel_step & low_mask(cfg.modulus_width);
  rate_cap_ = (modulus_ - 1) >> std::max(lead_bits_, 1u);
  require(accel_step_ <= rate_cap_, "accel_step must be below M / 2^max(lead bits, 1)");
  pos_mask_ = low_mask(cfg.pos_width);
  pos_sign_ = 1ull << (cfg.pos_width - 1);
  reset();
}

void GoldenInterp::reset() {
  decoder_.reset();
  next_ = DecodedBlock{};
  next_valid_ = false;
  next_taken_cycle_ = words_end_cycle_ = 0;
  feed_step_ = phase_ = 0;
  saturated_ = false;
  rate_ = rate_base_ = product_ = 0;
  rapid_ = false;
  override_ = kOverrideOne;
  mul_left_ = 0;
  slack_ = 0;
  held_ = false;
  stop_ = 0;
  after_tool_off_ = after_stop_ = after_optional_stop_ = false;
  dir_[0] = dir_[1] = false;
  circle_ = CircleDda{};
  serial_ = SerialDda(cfg_.inc_width);
  player_done_ = true;
  player_running_ = false;
  out_ = InterpOutputs{};
  out_.frame_ready = decoder_.ready();
  cycle_ = 0;
  loads_ = 0;
  fault_active_ = false;
  fault_cycle_ = fault_.kind == Fault::kNone ? std::numeric_limits<uint64_t>::max() : fault_.cycle;
}

uint64_t GoldenInterp::quiet_ticks(const InterpInputs& in) const {
  using State = GoldenTapeDecoder::State;
  if ((in.hold || (held_ && !in.start)) != held_) return 0;  // the hold register changes
  if (accel_step_ > 0 && (mul_left_ > 0 || override_input(in) != override_))
    return 0;  // the override's multiplier runs, or the override changes
  if ((in.estop || in.limit_x || in.limit_y) && !out_.done && !out_.error) return 0;  // a stop latches
  if (out_.paused && in.start) return 0;  // cycle start ends the pause
  if (out_.step_x || out_.step_y) return 0;  // the next edge clears them
  const bool busy = out_.busy;
  const bool buffer_empty = !next_valid_;
  if (busy && player_done_) return 0;       // the block ends: a load, or busy falls
  // A load (or the RAM read before it); none while paused (and then not busy: only the
  // decoder may move, below).
  if (!busy && !buffer_empty && !out_.paused) return 0;
  const State dstate = decoder_.state();
  if (!busy && buffer_empty && !out_.paused &&
      ((dstate == State::kError && !out_.error) ||
       (dstate == State::kEnd && decoder_.tape_ended() && !out_.done && stop_ == 0)))
    return 0;                               // status_edge() raises error or done
  if (!decoder_.quiet(in, buffer_empty)) return 0;
  uint64_t n = std::numeric_limits<uint64_t>::max();
  if (fault_cycle_ != std::numeric_limits<uint64_t>::max())
    n = fault_cycle_ > cycle_ + 1 ? fault_cycle_ - cycle_ - 1 : 0;  // fault_edge() at fault_cycle_
  if (busy) {
    // A running serial iteration ignores strobes: its own pulse, words and end edges bound
    // the jump. Otherwise a saturated block strobes at every edge.
    const bool ramped = accel_step_ > 0;
    // Held at rest, or stopped, the feed generator does nothing.
    const bool stopped = stop_ != 0 || (ramped ? halted() && rate_ == 0 : held_);
    if (player_running_)
      n = std::min(n, serial_.quiet_edges());
    else if (saturated_ && !ramped && !stopped)
      return 0;
    if (stopped) return n;
    // With ramps only a cruise is quiet: u as close below its target as du allows, and
    // each edge j stays there while K - j u > u.
    if (ramped) {
      const uint64_t target = ramp_target();
      if (halted() || rate_ == 0 || rate_ > target || rate_ + accel_step_ <= target ||
          slack_ <= rate_)
        return 0;
      n = std::min(n, static_cast<uint64_t>((slack_ - 1) / static_cast<__int128>(rate_)));
    }
    // The feed generator strobes at the first edge j with phase + j S >= M (phase < M).
    const uint64_t s = ramped ? rate_ : feed_step_;
    if ((ramped || !saturated_) && s > 0) {
      const uint64_t first_strobe = (modulus_ - phase_ + s - 1) / s;
      n = std::min(n, first_strobe - 1);
    }
  }
  return n;
}

void GoldenInterp::skip(uint64_t n) {
  cycle_ += n;
  if (out_.busy && !player_done_ && stop_ == 0 &&
      !(accel_step_ > 0 ? halted() && rate_ == 0 : held_)) {
    if (accel_step_ > 0) {  // a cruise: no strobe, u stays
      phase_ += n * rate_;
      slack_ -= static_cast<__int128>(n) * rate_;
    } else if (!saturated_) {
      phase_ += n * feed_step_;  // < M: no strobe
    }
  }
  if (player_running_) serial_.skip(n);
}

void GoldenInterp::load_block() {
  const DecodedBlock& b = next_;
  if (b.is_arc()) {
    // The decoder has checked the arc; the geometry gives the circle DDA's start.
    const ArcGeometry g = arc_geometry(b.arc_words(), cfg_.inc_width);
    if (cfg_.serial())
      serial_.load(g, !b.dx_neg, !b.dy_neg);
    else
      circle_.load(g, !b.dx_neg, !b.dy_neg);
  } else {
    // k = bit length of max(|dx|, |dy|); the RTL's decoder computes the same at the LF.
    const unsigned k = bit_length(b.dx | b.dy);
    if (cfg_.serial())
      serial_.load_line(k, b.dx, b.dy, !b.dx_neg, !b.dy_neg);
    else
      circle_.load_line(k, b.dx, b.dy, !b.dx_neg, !b.dy_neg);
  }
  player_done_ = cfg_.serial() ? serial_.done() : circle_.done();
  player_running_ = false;
  dir_[0] = !b.dx_neg;
  dir_[1] = !b.dy_neg;
  // Feed generator: the phase starts lead_bits_ doublings of S ahead (only an unsaturated
  // block uses it, and then S << lead_bits_ < M).
  feed_step_ = b.step;
  saturated_ = b.step_over || feed_step_ >= saturation_step_;
  phase_ = saturated_ ? 0 : feed_step_ << lead_bits_;
  if (accel_step_ > 0) {
    // A ramped block starts from standstill: u = 0, the phase empty, N M phase units to go.
    rate_base_ = b.step_over ? rate_cap_ : std::min(feed_step_, rate_cap_);
    rapid_ = b.motion == static_cast<uint8_t>(tape::Motion::kRapid);
    rate_ = 0;
    phase_ = 0;
    slack_ = static_cast<__int128>(b.iterations) * modulus_;
  }
  after_tool_off_ = b.tool_off;
  after_stop_ = b.stop;
  after_optional_stop_ = b.optional_stop;
  next_valid_ = false;
  out_.dir_x = dir_[0];
  out_.dir_y = dir_[1];
  out_.block_n = b.n;
  out_.busy = true;
  out_.feed_saturated = saturated_;
  ++loads_;
}

// feed_generator.sv's override_q and its multiplier: a load or a change of P to anything
// but 100 % restarts it, and kOverrideWidth edges later the target is the product, its
// fraction bits dropped (the RTL's shifts drop only those), capped. Its partial sums are
// not visible: only when it ends matters.
void GoldenInterp::multiplier_edge(const InterpInputs& in, bool load) {
  const uint16_t p = override_input(in);
  if (p != kOverrideOne && (load || p != override_)) {
    mul_left_ = kOverrideWidth;
    const unsigned __int128 scaled = static_cast<unsigned __int128>(rate_base_) * p;
    product_ = static_cast<uint64_t>(std::min<unsigned __int128>(scaled >> kOverrideFracBits, rate_cap_));
  } else if (mul_left_ > 0) {
    --mul_left_;
  }
  override_ = p;
}

void GoldenInterp::frame_edge(const InterpInputs& in, bool buffer_empty) {
  if (decoder_.state() == GoldenTapeDecoder::State::kHold && buffer_empty) {
    next_ = decoder_.block();  // the buffer takes the held block at this edge
    next_valid_ = true;
    next_taken_cycle_ = cycle_;
  }
  decoder_.edge(in, buffer_empty);
  out_.frame_ready = decoder_.ready();
}

void GoldenInterp::status_edge() {
  using State = GoldenTapeDecoder::State;
  if (decoder_.state() == State::kError && !out_.error) {
    out_.error = true;
    out_.error_code = static_cast<uint8_t>(decoder_.error_code());
    out_.error_block = decoder_.error_block();
    out_.error_offset = decoder_.error_offset();
  } else if (decoder_.state() == State::kEnd && decoder_.tape_ended() && stop_ == 0) {
    // (an end raised at the edge where a stop latches is taken back by stop_edge())
    out_.done = true;
  }
}

// interp_top's stop_q: E-stop before the X limit before the Y limit. The report names the
// block playing (or the last played) and no tape offset.
void GoldenInterp::stop_edge(const InterpInputs& in) {
  stop_ = in.estop ? 1 : in.limit_x ? 2 : 3;
  out_.error = true;
  out_.error_code = static_cast<uint8_t>(in.estop     ? TapeError::kEmergencyStop
                                         : in.limit_x ? TapeError::kLimitX
                                                      : TapeError::kLimitY);
  out_.error_block = out_.block_n;
  out_.error_offset = 0;
  out_.done = false;  // only an end raised at this edge: a stop latches while not done
}

void GoldenInterp::inject(const Fault& fault) {
  fault_ = fault;
  fault_active_ = false;
  fault_cycle_ = fault.kind == Fault::kNone ? std::numeric_limits<uint64_t>::max()
                                            : (fault.cycle > cycle_ ? fault.cycle : cycle_ + 1);
}

void GoldenInterp::fault_edge() {
  const int a = fault_.axis == 0 ? 0 : 1;
  bool& step = a == 0 ? out_.step_x : out_.step_y;
  bool& dir_out = a == 0 ? out_.dir_x : out_.dir_y;
  int64_t& pos = a == 0 ? out_.pos_x : out_.pos_y;
  const int64_t unit = dir_[a] ? 1 : -1;  // the direction the normal tick counted in
  bool again = true;                      // re-arm for the next cycle
  if (fault_active_ && (loads_ != fault_block_ || !out_.busy)) {
    // The faulty block has ended: the outputs of this edge are already the normal ones,
    // except a dir output inverted by the fault, which the new/idle state restores.
    if (fault_.kind == Fault::kWrongDirection && loads_ == fault_block_) dir_out = dir_[a];
    fault_active_ = false;
    again = false;
  } else {
    switch (fault_.kind) {
      case Fault::kNone: again = false; break;
      case Fault::kLostPulse:
        if (step) {
          step = false;
          pos = wrap_position(pos - unit);
          again = false;
        }
        break;
      case Fault::kStuckStep:
        if (!out_.busy) break;  // waits for a block
        if (!fault_active_) {
          fault_active_ = true;
          fault_block_ = loads_;
        }
        if (!step) {
          step = true;
          pos = wrap_position(pos + unit);
        }
        break;
      case Fault::kAccumulatorOffByOne:
        if (!out_.busy) break;
        player_dda().add_to_integrator(a, 1);
        again = false;
        break;
      case Fault::kWrongDirection:
        if (!out_.busy) break;
        if (!fault_active_) {
          fault_active_ = true;
          fault_block_ = loads_;
        }
        dir_out = !dir_[a];
        if (step) pos = wrap_position(pos - 2 * unit);
        break;
    }
  }
  if (again) {
    fault_cycle_ = cycle_ + 1;
  } else {
    fault_cycle_ = std::numeric_limits<uint64_t>::max();
    fault_.kind = Fault::kNone;
  }
}

}  // namespace ncinterp
