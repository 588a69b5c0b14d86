// When each pulse of a line block must come, from the documented timing of the
// interpolator (docs/interpolator.md section 5), in closed form.
// Idea: a line block with k = bit length of max(|dx|, |dy|) takes 2^k DDA iterations, each
// 2^lead clocks long (lead 0: the one-clock DDA; with BitSerial the serial DDA's 2P, whose
// feed generator starts the phase S << lead: feed_generator.sv). Iteration j (L = the load
// edge, M = feed modulus, S = F << k for G01, the rapid step for G00: line_step()) starts
//     at edge L + ceil(j M / S) - 2^lead   when S << lead < M,
//     at edge L + 1 + 2^lead (j - 1)       when saturated (S << lead >= M),
// its pulses come k - 1 edges later with lead > 0 (the serial DDA's clock k - 1; at once
// with lead 0), and after it an axis of |d| has emitted floor((2^(k-1) + j |d|) / 2^k)
// pulses. The block lasts C = ceil(M 2^k / S) clocks (ceil(M / F) for G01; 2^lead 2^k + 1
// saturated) from its load
// edge to the next load. The checker compares every clock's pulse counts with these
// numbers, so a missing, extra, early or late pulse is reported at the very clock it
// happens. This is the documented behaviour written as formulas, not the engines'
// register-level code.
#pragma once
#include <cstdint>

#include "interp_ports.h"

namespace ncinterp::checker {

class LineSchedule {
 public:
  LineSchedule() = default;
  // A straight block (G01 or G00) on the machine cfg.
  LineSchedule(const tape::Block& b, const InterpConfig& cfg);
  // A line of |dx|, |dy| whose 2^k iterations come at the feed step S (line_step()).
  LineSchedule(uint64_t dx_abs, uint64_t dy_abs, unsigned __int128 step, uint64_t feed_modulus,
               unsigned lead_bits = 0);

  unsigned k() const { return k_; }
  uint64_t iterations() const { return kpow_; }  // 2^k
  bool saturated() const { return saturated_; }
  // Clocks from the load edge to the next load edge (or busy falling).
  uint64_t duration() const { return duration_; }
  // Edge (counted from the load edge = 0) of iteration j's pulses (1..2^k).
  uint64_t iteration_edge(uint64_t j) const;
  // Pulses of an axis of magnitude d after j iterations.
  uint64_t pulses(uint64_t d, uint64_t j) const;

 private:
  unsigned k_ = 0;
  uint64_t kpow_ = 1;
  uint64_t step_ = 0;     // S (M when saturated)
  uint64_t modulus_ = 1;  // M
  unsigned lead_ = 0;     // log2 of an iteration's clocks
  uint64_t delay_ = 0;    // from an iteration's start to its pulses
  bool saturated_ = false;
  uint64_t duration_ = 0;
};

}  // namespace ncinterp::checker
