// Floating-point arithmetic for the schemes (circle_scheme.h, line_scheme.h): double, the
// precision the study is run in, and long double, used only to tell which double results
// are limited by round-off (method_study.cpp).
// Idea: every scheme is written once against a small arithmetic interface (coefficient
// times value, add, subtract, halve); FloatArith and FixedArith (fixed_arith.h) implement it,
// so the double and the fixed-point interpolators are the same code.
#pragma once
#include "op_count.h"

namespace ncinterp::sampled {

template <class Real>
class FloatArith {
 public:
  using Value = Real;  // a coordinate
  using Coef = Real;   // a constant of the scheme (h, 0.5 h, 2 h, 0.5 h^2)

  Coef coef(long double c) const { return static_cast<Real>(c); }
  Value from_real(long double v) const { return static_cast<Real>(v); }
  long double to_real(Value v) const { return v; }
  // Size of one unit of the last place of a coordinate; 0: not a fixed-point format.
  double quantum() const { return 0.0; }

  Value mul(Coef c, Value v) {
    ++ops_.mul;
    return c * v;
  }
  Value add(Value a, Value b) {
    ++ops_.add;
    return a + b;
  }
  Value sub(Value a, Value b) {
    ++ops_.add;
    return a - b;
  }
  Value half(Value v) {
    ++ops_.shift;
    return v / 2;
  }

  const OpCount& ops() const { return ops_; }

 private:
  OpCount ops_;
};

}  // namespace ncinterp::sampled
