// Documented pulse timing of a line block (see line_schedule.h).
#include "line_schedule.h"

#include <algorithm>

namespace ncinterp::checker {

LineSchedule::LineSchedule(uint64_t dx_abs, uint64_t dy_abs, uint64_t feed, uint64_t feed_modulus)
    : modulus_(feed_modulus ? feed_modulus : 1) {
  const uint64_t big = std::max(dx_abs, dy_abs);
  while (k_ < 63 && (big >> k_) != 0) ++k_;
  kpow_ = uint64_t{1} << k_;
  const unsigned __int128 s = static_cast<unsigned __int128>(feed) << k_;
  saturated_ = s >= modulus_;
  step_ = saturated_ ? modulus_ : static_cast<uint64_t>(s);
  duration_ = saturated_ ? kpow_ + 1 : (feed ? (modulus_ + feed - 1) / feed : 0);
}

uint64_t LineSchedule::iteration_edge(uint64_t j) const {
  if (saturated_) return j;
  if (step_ == 0) return UINT64_MAX;
  const unsigned __int128 num = static_cast<unsigned __int128>(j) * modulus_;
  return static_cast<uint64_t>((num + step_ - 1) / step_) - 1;
}

uint64_t LineSchedule::pulses(uint64_t d, uint64_t j) const {
  const unsigned __int128 v = static_cast<unsigned __int128>(kpow_ >> 1) +
                              static_cast<unsigned __int128>(j) * d;
  return static_cast<uint64_t>(v >> k_);
}

}  // namespace ncinterp::checker
