// Fixed-point arithmetic (see fixed_arith.h).
#include "fixed_arith.h"

#include <cmath>
#include <stdexcept>
#include <string>

namespace ncinterp::sampled {

FixedFormat FixedFormat::for_magnitude(double max_abs, int word_bits) {
  if (word_bits < 2 || word_bits > 62) throw std::invalid_argument("word length must be 2..62 bits");
  if (!(max_abs > 0) || !std::isfinite(max_abs)) throw std::invalid_argument("magnitude must be positive");
  int e = 0;
  std::frexp(max_abs, &e);  // 2^(e-1) <= max_abs < 2^e: e integer bits
  return FixedFormat{word_bits, word_bits - 1 - e};
}

double FixedFormat::quantum() const { return std::ldexp(1.0, -frac_bits); }

FixedArith::FixedArith(FixedFormat format)
    : format_(format), max_raw_((int64_t{1} << (format.word_bits - 1)) - 1) {}

FixedArith::Coef FixedArith::coef(long double c) const {
  if (c == 0) return Coef{};
  const int b = format_.word_bits;
  int e = 0;
  const long double m = std::frexp(c, &e);  // 0.5 <= |m| < 1
  int64_t mantissa = std::llround(std::ldexp(m, b - 1));
  if (std::llabs(mantissa) > max_raw_) {  // rounded up to 2^(B-1): halve, exactly
    mantissa /= 2;
    ++e;
  }
  const int shift = b - 1 - e;
  if (shift < 1 || shift > 120) throw std::invalid_argument("constant out of the fixed-point range");
  return Coef{mantissa, shift};
}

FixedArith::Value FixedArith::from_real(long double v) const {
  const long double scaled = std::ldexp(v, format_.frac_bits);
  if (!(std::fabs(scaled) <= static_cast<long double>(max_raw_)))
    throw std::overflow_error("fixed point: " + std::to_string(static_cast<double>(v)) + " does not fit a " +
                              std::to_string(format_.word_bits) + "-bit word");
  return std::llround(scaled);
}

long double FixedArith::to_real(Value v) const {
  return std::ldexp(static_cast<long double>(v), -format_.frac_bits);
}

FixedArith::Value FixedArith::checked(__int128 v) const {
  if (v > max_raw_ || v < -static_cast<__int128>(max_raw_))
    throw std::overflow_error("fixed point: a coordinate overflows the " + std::to_string(format_.word_bits) +
                              "-bit word");
  return static_cast<Value>(v);
}

FixedArith::Value FixedArith::mul(Coef c, Value v) {
  ++ops_.mul;
  const __int128 product = static_cast<__int128>(c.mantissa) * v;
  // Round to nearest: add half a quantum, then an arithmetic (flooring) shift.
  return checked((product + (static_cast<__int128>(1) << (c.shift - 1))) >> c.shift);
}

FixedArith::Value FixedArith::add(Value a, Value b) {
  ++ops_.add;
  return checked(static_cast<__int128>(a) + b);
}

FixedArith::Value FixedArith::sub(Value a, Value b) {
  ++ops_.add;
  return checked(static_cast<__int128>(a) - b);
}

FixedArith::Value FixedArith::half(Value v) {
  ++ops_.shift;
  return (v + 1) >> 1;  // round to nearest, ties upward (arithmetic shift floors)
}

}  // namespace ncinterp::sampled
