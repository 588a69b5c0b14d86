// Fixed-point arithmetic for the schemes: B-bit two's-complement words, as in the
// microprocessor CNCs the paper describes.
// Idea: a coordinate is an integer number of quanta 2^-F (F fraction bits), F chosen so
// that the largest magnitude the caller expects (twice the radius: K6 as written reaches
// 1.41 R, and K1 grows) just fits the word. A constant of the scheme (h, 0.5 h, 2 h,
// 0.5 h^2) is stored as a B-bit mantissa with its own binary point (as one scales
// constants for a fixed-point multiplier), so even 0.5 h^2 = 5e-9 keeps B - 1 significant
// bits. A product is formed at full width and rounded to the nearest quantum (ties
// upward); halving rounds the same way. Any result outside the word throws
// std::overflow_error: a fixed-point interpolator cannot silently wrap.
#pragma once
#include <cstdint>

#include "op_count.h"

namespace ncinterp::sampled {

struct FixedFormat {
  int word_bits = 32;  // B, sign included
  int frac_bits = 0;   // F: a coordinate is an integer times 2^-F

  // The format with the most fraction bits whose range (+-2^(B-1-F)) exceeds max_abs.
  static FixedFormat for_magnitude(double max_abs, int word_bits);
  double quantum() const;  // 2^-F
};

class FixedArith {
 public:
  using Value = int64_t;
  struct Coef {
    int64_t mantissa = 0;  // B-bit signed
    int shift = 1;         // the constant is mantissa * 2^-shift
  };

  explicit FixedArith(FixedFormat format);

  Coef coef(long double c) const;
  Value from_real(long double v) const;  // rounded to the nearest quantum
  long double to_real(Value v) const;
  double quantum() const { return format_.quantum(); }
  const FixedFormat& format() const { return format_; }

  Value mul(Coef c, Value v);
  Value add(Value a, Value b);
  Value sub(Value a, Value b);
  Value half(Value v);

  const OpCount& ops() const { return ops_; }

 private:
  Value checked(__int128 v) const;  // throws std::overflow_error outside the word

  FixedFormat format_;
  int64_t max_raw_;  // 2^(B-1) - 1
  OpCount ops_;
};

}  // namespace ncinterp::sampled
