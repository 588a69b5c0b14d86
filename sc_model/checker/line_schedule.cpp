// Documented pulse timing of a line block (see line_schedule.h).
#include "line_schedule.h"

#include <algorithm>

namespace ncinterp::checker {

LineSchedule::LineSchedule(uint64_t dx_abs, uint64_t dy_abs, uint64_t feed, uint64_t feed_modulus,
                           unsigned lead_bits)
    : modulus_(feed_modulus ? feed_modulus : 1), lead_(lead_bits) {
  const uint64_t big = std::max(dx_abs, dy_abs);
  while (k_ < 63 && (big >> k_) != 0) ++k_;
  kpow_ = uint64_t{1} << k_;
  delay_ = lead_ == 0 || k_ == 0 ? 0 : k_ - 1;
  const unsigned __int128 s = static_cast<unsigned __int128>(feed) << k_;
  saturated_ = s << lead_ >= modulus_;
  step_ = saturated_ ? modulus_ : static_cast<uint64_t>(s);
  duration_ = saturated_ ? (kpow_ << lead_) + 1 : (feed ? (modulus_ + feed - 1) / feed : 0);
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
