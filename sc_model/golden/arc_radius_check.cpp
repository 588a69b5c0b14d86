// Radius check of an arc block, clock by clock (see arc_radius_check.h); each case is the
// phase of the same name in rtl/arc_radius_check.sv, and every register is written as
// there.
#include "arc_radius_check.h"

namespace ncinterp {

void ArcRadiusCheck::step(const ArcGeometry& g) {
  const unsigned sq_width = 2 * w_ + 4, e_width = w_ + 2;
  const auto bit = [](u128 v, unsigned b) { return ((v >> b) & 1u) != 0; };
  const bool first_bit = bit_ == 0, last_bit = bit_ == sq_width - 1;

  // The serial adder of this clock.
  const uint64_t v = phase_ == Phase::kSumA ? (second_ ? g.y0 : g.x0)
                                            : (second_ ? g.y1 : g.x1);
  const uint64_t u = phase_ == Phase::kSq ? e_ : v;
  const bool in_range = bit_ >= pass_ && bit_ - pass_ < e_width;
  const bool neg = first_bit ? bit(acc_, sq_width - 1) : neg_;
  const bool invert = phase_ == Phase::kCopy || (phase_ == Phase::kAbs && neg);
  const bool carry_in0 = phase_ == Phase::kAbs && neg;
  const bool sums = phase_ == Phase::kSumA || phase_ == Phase::kSumB || phase_ == Phase::kSq;
  const bool addend = sums && bit(u, pass_) && in_range && bit(u, bit_ - pass_);
  const bool cin = first_bit ? carry_in0 : carry_;
  const unsigned total = unsigned(bit(acc_, 0) != invert) + addend + cin;
  const bool sum = (total & 1u) != 0, cout = total >= 2;
  const bool four_a_bit = bit(a_, sq_width - 2);  // A's bit i - 2 (4A's bit i)
  const bool le = (!sum && four_a_bit) || (sum == four_a_bit && (first_bit || le_));

  const auto rotate_in = [sq_width](u128 word, bool top) {
    return (word >> 1) | (u128{top} << (sq_width - 1));
  };
  // Every clock: one bit through the adder, the accumulator one place round.
  const unsigned i = bit_;
  bit_ = last_bit ? 0 : i + 1;
  carry_ = cout;
  switch (phase_) {
    case Phase::kSumA:
    case Phase::kSumB:
      acc_ = rotate_in(acc_, sum);
      if (last_bit && pass_++ == w_ - 1) {
        pass_ = 0;
        if (second_) phase_ = phase_ == Phase::kSumA ? Phase::kCopy : Phase::kAbs;
        second_ = !second_;
      }
      return;
    case Phase::kCopy:
      a_ = rotate_in(a_, bit(acc_, 0));
      acc_ = rotate_in(acc_, sum);
      if (last_bit) phase_ = Phase::kSumB;
      return;
    case Phase::kAbs:
      neg_ = neg;
      acc_ = rotate_in(acc_, false);
      if (i < e_width)
        e_ = (e_ >> 1) | (uint64_t{sum} << (e_width - 1));
      else
        far_ = far_ || sum;
      if (last_bit) phase_ = Phase::kSq;
      return;
    case Phase::kSq:
      acc_ = rotate_in(acc_, sum);
      a_ = rotate_in(a_, bit(a_, 0));
      le_ = le;
      if (last_bit && pass_++ == e_width - 1) phase_ = Phase::kDone;
      return;
    case Phase::kDone:
      return;
  }
}

}  // namespace ncinterp
