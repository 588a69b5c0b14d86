// ISO 840 even parity: bit 7 of each frame makes the number of ones in the 8 bits even.
#include "tape.h"

namespace ncinterp::tape {

bool has_even_parity(uint8_t frame) { return __builtin_parity(frame) == 0; }

std::vector<uint8_t> add_parity(std::string_view text) {
  std::vector<uint8_t> frames;
  frames.reserve(text.size());
  for (const char ch : text) {
    const uint8_t c = static_cast<uint8_t>(ch) & 0x7f;
    frames.push_back(has_even_parity(c) ? c : static_cast<uint8_t>(c | 0x80));
  }
  return frames;
}

}  // namespace ncinterp::tape
