// Documented pulse timing of a line block (see line_schedule.h).
#include "line_schedule.h"

#include <algorithm>
#include <cstdlib>

#include "dda_serial.h"

namespace ncinterp::checker {

LineSchedule::LineSchedule(const tape::Block& b, const InterpConfig& cfg)
    : LineSchedule(static_cast<uint64_t>(std::llabs(b.dx)), static_cast<uint64_t>(std::llabs(b.dy)),
                   line_step(b, cfg), cfg.feed_modulus, SerialDda::player_lead_bits(cfg)) {}

LineSchedule::LineSchedule(uint64_t dx_abs, uint64_t dy_abs, unsigned __int128 step, uint64_t feed_modulus,
                           unsigned lead_bits)
    : modulus_(feed_modulus ? feed_modulus : 1), lead_(lead_bits) {
  k_ = bit_length(std::max(dx_abs, dy_abs));
  kpow_ = uint64_t{1} << k_;
  delay_ = lead_ == 0 || k_ == 0 ? 0 : k_ - 1;
  saturated_ = step << lead_ >= modulus_;
  step_ = saturated_ ? modulus_ : static_cast<uint64_t>(step);
  const unsigned __int128 programmed = static_cast<unsigned __int128>(modulus_) << k_;
  duration_ = saturated_ ? (kpow_ << lead_) + 1
                         : (step ? static_cast<uint64_t>((programmed + step - 1) / step) : 0);
}

uint64_t LineSchedule::iteration_edge(uint64_t j) const {
  const uint64_t clocks = uint64_t{1} << lead_;
  if (saturated_) return 1 + clocks * (j - 1) + delay_;
  if (step_ == 0) return UINT64_MAX;
  const unsigned __int128 num = static_cast<unsigned __int128>(j) * modulus_;
  return static_cast<uint64_t>((num + step_ - 1) / step_) - clocks + delay_;
}

uint64_t LineSchedule::pulses(uint64_t d, uint64_t j) const {
  const unsigned __int128 v = static_cast<unsigned __int128>(kpow_ >> 1) +
                              static_cast<unsigned __int128>(j) * d;
  return static_cast<uint64_t>(v >> k_);
}

}  // namespace ncinterp::checker
