// Radius check of an arc block, clock by clock (see arc_radius_check.h); each case is the
// phase of the same name in rtl/arc_radius_check.sv.
#include "arc_radius_check.h"

namespace ncinterp {

void ArcRadiusCheck::step(const ArcGeometry& g) {
  const unsigned sq_width = 2 * w_ + 4, e_width = w_ + 2;
  const u128 mask = (u128{1} << sq_width) - 1;
  const auto bit = [](u128 v, unsigned b) { return ((v >> b) & 1u) != 0; };
  switch (phase_) {
    case Phase::kSumA:
    case Phase::kSumB: {
      const bool a = phase_ == Phase::kSumA;
      const u128 v = second_ ? (a ? g.y0 : g.y1) : (a ? g.x0 : g.x1);
      const u128 sum = ((second_ ? acc_ : acc_ << 1) + (bit(v, bit_) ? v : 0)) & mask;
      acc_ = sum;
      if (second_) {
        if (bit_ == 0) {
          bit_ = w_ - 1;
          if (a) {
            a_ = sum & ((u128{1} << (2 * w_ + 1)) - 1);
            acc_ = 0;
            phase_ = Phase::kSumB;
          } else {
            phase_ = Phase::kDiff;
          }
        } else {
          --bit_;
        }
      }
      second_ = !second_;
      return;
    }
    case Phase::kDiff:
      acc_ = (acc_ + (~a_ & mask)) & mask;  // B - A - 1
      phase_ = Phase::kAbs;
      return;
    case Phase::kAbs:
      if (bit(acc_, sq_width - 1)) acc_ = (~acc_ + 1) & mask;
      phase_ = Phase::kSplit;
      return;
    case Phase::kSplit:
      far_ = (acc_ >> e_width) != 0;
      e_ = acc_ & ((u128{1} << e_width) - 1);
      acc_ = 0;
      bit_ = e_width - 1;
      phase_ = Phase::kSq;
      return;
    case Phase::kSq:
      acc_ = ((acc_ << 1) + (bit(e_, bit_) ? e_ : 0)) & mask;
      if (bit_ == 0)
        phase_ = Phase::kDone;
      else
        --bit_;
      return;
    case Phase::kDone:
      return;
  }
}

}  // namespace ncinterp
