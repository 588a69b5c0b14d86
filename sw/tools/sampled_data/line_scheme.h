// L1: the paper's line interpolator, one period at a time, on any arithmetic.
// Idea: a line needs no integration of a curve: every period each axis k moves by the
// same reference word h_k = V L_k T / L (V feed, T period, L_k the block's move along the
// axis, L its length), computed once per block: Y+ = Y + h_k. Whatever error L1 makes comes
// from rounding h_k to the word and from L not being a whole number of steps V T.
#pragma once
#include <cmath>

namespace ncinterp::sampled {

template <class Arith>
class LineScheme {
 public:
  using Value = typename Arith::Value;
  struct Point {
    Value x, y;
  };

  // The block's move (lx, ly) and the path length per period V T.
  LineScheme(long double lx, long double ly, long double step_length, Arith& arith)
      : a_(arith),
        hx_(arith.from_real(step_length * lx / std::hypot(lx, ly))),
        hy_(arith.from_real(step_length * ly / std::hypot(lx, ly))) {}

  void start(Point p) { cur_ = p; }

  Point step() {
    cur_ = {a_.add(cur_.x, hx_), a_.add(cur_.y, hy_)};
    return cur_;
  }

  Point point() const { return cur_; }

 private:
  Arith& a_;
  Value hx_, hy_;  // the reference words h_k
  Point cur_{};
};

}  // namespace ncinterp::sampled
