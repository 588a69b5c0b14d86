// The bit length of an unsigned value: the position of its highest 1 plus one (0 for 0).
// Idea: one definition for every place that needs a DDA's k (a line's 2^k iterations, an
// arc's modulus 2^k, register widths); the RTL's is the decoder's bit_length function.
#pragma once
#include <cstdint>

namespace ncinterp {

constexpr unsigned bit_length(uint64_t v) {
  unsigned n = 0;
  while (n < 64 && (v >> n) != 0) ++n;
  return n;
}

}  // namespace ncinterp
