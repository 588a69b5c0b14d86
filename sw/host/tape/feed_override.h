// The operator's feed and rapid overrides as the interpolator takes them (interp_top's
// feed_override_i and rapid_override_i, docs/motion-control.md): the fraction of the rate a
// block plays at, in units of 1 / 2^kOverrideFracBits, kOverrideWidth bits wide, so 0 to
// 200 % in steps of 1/128 (0.78 %). A binary fraction, so that the hardware scales by a
// multiply and a shift, not a division; the command line takes percent and rounds.
// interp_pkg_gen writes both into rtl/0_interp_pkg.sv: one definition for the two languages,
// and the boards' override buttons' steps (override_units() of 0, 10, ..., 200 %) as
// interp_pkg::override_of_tens().
#pragma once
#include <cmath>
#include <cstdint>

namespace ncinterp {

constexpr unsigned kOverrideFracBits = 7;
constexpr unsigned kOverrideOne = 1u << kOverrideFracBits;  // 100 %
constexpr unsigned kOverrideWidth = kOverrideFracBits + 2;  // up to 200 % (2 * kOverrideOne)
// The feed override buttons' steps: 10 % each, 0 to 200 %, 100 % at reset.
constexpr unsigned kOverrideTens = 20;
constexpr unsigned kOverrideTensAtOne = kOverrideTens / 2;

// A percentage (0 to 200) in units of 1 / kOverrideOne, rounded to the nearest.
inline uint16_t override_units(double percent) {
  return static_cast<uint16_t>(std::llround(percent * kOverrideOne / 100));
}

}  // namespace ncinterp
