// Radius check of an arc block, clock by clock: the C++ twin of rtl/arc_radius_check.sv
// (same registers, same schedule). The exact formula it computes is arc_end_on_circle()
// (arc_geometry.h): (B - A - 1)^2 <= 4A with A = x0^2 + y0^2, B = x1^2 + y1^2.
// Idea: bit-serial arithmetic on a one-bit full adder; the accumulator circulates, one bit
// per clock, LSB first, a pass of L = 2W + 4 clocks taking it once round. A = sum of the
// squares by shift-and-add passes, a copy of A with acc = ~A, B added the same way (E = B
// - A - 1), |E| by ~E + 1, |E|^2 by passes again, compared with 4A bit by bit:
// (5W + 4) passes, (5W + 4)(2W + 4) clocks.
#pragma once
#include <cstdint>

#include "arc_geometry.h"

namespace ncinterp {

class ArcRadiusCheck {
 public:
  explicit ArcRadiusCheck(unsigned inc_width) : w_(inc_width) {}

  // Clocks from the start edge to done.
  static uint64_t clocks(unsigned inc_width) {
    return uint64_t(5 * inc_width + 4) * (2 * inc_width + 4);
  }

  // The start edge (start_i).
  void start() {
    phase_ = Phase::kSumA;
    pass_ = 0;
    bit_ = 0;
    second_ = false;
    acc_ = 0;
    far_ = false;
  }
  bool done() const { return phase_ == Phase::kDone; }
  bool ok() const { return !far_ && le_; }
  // One edge of the running check (!done()); g holds x0, y0, x1, y1.
  void step(const ArcGeometry& g);

 private:
  using u128 = unsigned __int128;
  enum class Phase : uint8_t { kSumA, kCopy, kSumB, kAbs, kSq, kDone };

  unsigned w_;
  Phase phase_ = Phase::kDone;
  unsigned pass_ = 0;    // b: the pass within a square
  unsigned bit_ = 0;     // i: the clock within a pass
  bool second_ = false;  // the y term of a sum of squares
  // acc_, a_: 2W + 4 bits (68 at W = 32: 128-bit), circulating: bit i of the word is at
  // bit 0 at clock i of a pass. e_ = |E| (W + 2 bits).
  u128 acc_ = 0, a_ = 0;
  uint64_t e_ = 0;
  bool carry_ = false;   // the serial adder's carry
  bool far_ = false;     // |E| >= 2^(W+2)
  bool neg_ = false;     // E < 0 (Abs)
  bool le_ = false;      // acc <= 4A in the bits so far (Sq)
};

}  // namespace ncinterp
