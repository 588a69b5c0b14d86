// Between the tape format and the interpolator's configuration (see interp_ports.h).
#include "interp_ports.h"

#include <cmath>
#include <stdexcept>

namespace ncinterp {

Arch parse_arch(const std::string& name) {
  if (name == "serial") return Arch::kSerial;
  if (name == "parallel") return Arch::kParallel;
  throw std::invalid_argument("unknown arch '" + name + "' (serial or parallel)");
}

InterpConfig interp_config(double clock_hz, const tape::Format& format, double rapid_mm_min,
                           double accel_mm_s2) {
  InterpConfig cfg;
  cfg.inc_width = format.inc_width;
  cfg.frac_digits = format.frac_digits;
  cfg.feed_frac_digits = format.feed_frac_digits;
  cfg.feed_width = format.feed_width;
  cfg.seq_width = format.seq_width;
  cfg.circle_mode = format.circle_mode;
  cfg.misc_functions = format.misc_functions;
  cfg.feed_modulus = InterpConfig::feed_modulus_for(clock_hz, format.feed_frac_digits);
  cfg.rapid_step = InterpConfig::rapid_step_for(rapid_mm_min, format.frac_digits, format.feed_frac_digits);
  if (accel_mm_s2 > 0) cfg.accel_step = ramp_step(accel_mm_s2, clock_hz, cfg);
  return cfg;
}

uint64_t ramp_step(double accel_mm_s2, double clock_hz, const InterpConfig& cfg) {
  const uint64_t du = InterpConfig::accel_step_for(accel_mm_s2, clock_hz, cfg.frac_digits, cfg.feed_modulus);
  if (du == 0) {
    // One step du = 1 stands for f^2 / (10^frac_digits M) mm/s^2.
    const double smallest =
        clock_hz * clock_hz / std::pow(10.0, cfg.frac_digits) / static_cast<double>(cfg.feed_modulus);
    throw std::invalid_argument("--accel " + std::to_string(accel_mm_s2) +
                                " mm/s^2 is below one ramp step at this clock: the smallest is " +
                                std::to_string(smallest) + " mm/s^2");
  }
  return du;
}

tape::Format tape_format_of(const InterpConfig& cfg) {
  tape::Format f;
  f.frac_digits = cfg.frac_digits;
  f.feed_frac_digits = cfg.feed_frac_digits;
  f.inc_width = cfg.inc_width;
  f.feed_width = cfg.feed_width;
  f.seq_width = cfg.seq_width;
  f.circle_mode = cfg.circle_mode;
  f.misc_functions = cfg.misc_functions;
  return f;
}

}  // namespace ncinterp
