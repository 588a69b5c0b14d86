// Radius check of an arc block, clock by clock: the C++ twin of rtl/arc_radius_check.sv
// (same registers, same schedule). The exact formula it computes is arc_end_on_circle()
// (arc_geometry.h): (B - A - 1)^2 <= 4A with A = x0^2 + y0^2, B = x1^2 + y1^2.
// Idea: one adder and one accumulator, serially: A and B by MSB-first shift-and-add (one
// term per clock), E = B + ~A, |E| = ~E + 1, |E|^2 by shift-and-add; 5W + 5 clocks.
#pragma once
#include <cstdint>

#include "arc_geometry.h"

namespace ncinterp {

class ArcRadiusCheck {
 public:
  explicit ArcRadiusCheck(unsigned inc_width) : w_(inc_width) {}

  // Clocks from the start edge to done.
  static unsigned clocks(unsigned inc_width) { return 5 * inc_width + 5; }

  // The start edge (start_i).
  void start() {
    phase_ = Phase::kSumA;
    bit_ = w_ - 1;
    second_ = false;
    acc_ = 0;
  }
  bool done() const { return phase_ == Phase::kDone; }
  bool ok() const { return !far_ && acc_ <= (a_ << 2); }
  // One edge of the running check (!done()); g holds x0, y0, x1, y1.
  void step(const ArcGeometry& g);

 private:
  using u128 = unsigned __int128;
  enum class Phase : uint8_t { kSumA, kSumB, kDiff, kAbs, kSplit, kSq, kDone };

  unsigned w_;
  Phase phase_ = Phase::kDone;
  unsigned bit_ = 0;     // the operand bit of this step
  bool second_ = false;  // the y term of a sum of squares
  // acc_: 2W + 4 bits (68 at W = 32: 128-bit). a_ = A. e_ = |E| (W + 2 bits).
  u128 acc_ = 0, a_ = 0, e_ = 0;
  bool far_ = false;     // |E| >= 2^(W+2)
};

}  // namespace ncinterp
