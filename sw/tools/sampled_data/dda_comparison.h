// The sampled-data methods against the project's hardware circle DDA on the same arcs: a
// full quadrant of radius R BLU from (R, 0) clockwise to (0, -R) (G02, I = -R).
// Idea: hold both to the same result, a path within 1 BLU of the circle, and compare what
// it costs. The hardware DDA (sc_model/golden/dda_circle.h, the RTL's C++ twin, called
// here, not re-implemented) emits one pulse at a time: iterations per quadrant, additions
// per iteration, k-bit registers. A sampled-data method sends one reference word per
// period: it takes the largest h (grid 0.1 * 2^(-j/4)) whose double-precision path,
// chords included, stays within 0.5 BLU, leaving the other half BLU to rounding, and then
// the shortest fixed-point word whose path stays within 1 BLU.
#pragma once
#include <cstdint>
#include <vector>

#include "method.h"
#include "op_count.h"

namespace ncinterp::sampled {

struct DdaQuadrant {
  int64_t radius_blu = 0;
  unsigned k = 0;                   // register width: bit length of R (modulus 2^k)
  uint64_t iterations = 0;
  uint64_t pulses = 0;              // both axes
  double max_radial_error_blu = 0;  // at every position after a pulse
  // Per iteration: two integrator additions, and per pulse a magnitude increment or
  // decrement and a counter decrement (dda_circle.h), measured from the pulse count.
  double additions_per_iteration() const;
};

// Throws std::invalid_argument when R is not a good quadrant arc for the hardware.
DdaQuadrant run_hardware_dda_quadrant(int64_t radius_blu);

struct SampledForOneBlu {
  Method method = Method::kK1;
  bool reached = false;     // some h on the grid holds the double path to 0.5 BLU
  double h = 0;             // the largest such h
  uint64_t periods = 0;     // per quadrant at that h
  double path_error_double_blu = 0;
  int word_bits = 0;        // shortest word with a fixed-point path within 1 BLU; 0: none up to 62
  double path_error_fixed_blu = 0;
  OpCount ops_per_period;
};

SampledForOneBlu sampled_for_one_blu(Method method, int64_t radius_blu, Starter starter);

struct ComparisonRow {
  int64_t radius_blu = 0;
  DdaQuadrant dda;
  std::vector<SampledForOneBlu> methods;  // K1..K7
};

std::vector<ComparisonRow> compare_with_hardware_dda(const std::vector<int64_t>& radii_blu, Starter starter);

}  // namespace ncinterp::sampled
