// Parsing "--widths LO:HI" (see width_range.h).
#include "width_range.h"

#include <stdexcept>

namespace ncinterp::sweep {
namespace {

unsigned parse_width(const std::string& text, const std::string& whole) {
  if (text.empty() || text.size() > 3 || text.find_first_not_of("0123456789") != std::string::npos)
    throw std::invalid_argument("--widths: '" + whole + "' is not LO:HI (two whole numbers of bits)");
  const unsigned w = static_cast<unsigned>(std::stoul(text));
  if (w < kMinWidth || w > kMaxWidth)
    throw std::invalid_argument("--widths: " + text + " is outside " + std::to_string(kMinWidth) + ".." +
                                std::to_string(kMaxWidth) + " bits");
  return w;
}

}  // namespace

WidthRange parse_width_range(const std::string& text) {
  const size_t colon = text.find(':');
  WidthRange r;
  if (colon == std::string::npos) {
    r.low = r.high = parse_width(text, text);
  } else {
    r.low = parse_width(text.substr(0, colon), text);
    r.high = parse_width(text.substr(colon + 1), text);
  }
  if (r.low > r.high)
    throw std::invalid_argument("--widths: " + text + " runs backwards (LO must be <= HI)");
  return r;
}

}  // namespace ncinterp::sweep
