// Names of the methods and starters (see method.h).
#include "method.h"

namespace ncinterp::sampled {

const char* method_name(Method m) {
  switch (m) {
    case Method::kL1: return "L1";
    case Method::kK1: return "K1";
    case Method::kK2: return "K2";
    case Method::kK3: return "K3";
    case Method::kK4: return "K4";
    case Method::kK5: return "K5";
    case Method::kK6: return "K6";
    case Method::kK7: return "K7";
  }
  return "?";
}

const char* method_description(Method m) {
  switch (m) {
    case Method::kL1: return "line";
    case Method::kK1: return "Euler";
    case Method::kK2: return "improved polygon";
    case Method::kK3: return "two-step Euler";
    case Method::kK4: return "new X at once";
    case Method::kK5: return "K4, order alternating";
    case Method::kK6: return "K5 in one period";
    case Method::kK7: return "Taylor";
  }
  return "?";
}


std::optional<Starter> parse_starter(std::string_view text) {
  if (text == "k1" || text == "K1") return Starter::kK1;
  if (text == "k7" || text == "K7") return Starter::kK7;
  return std::nullopt;
}

}  // namespace ncinterp::sampled
