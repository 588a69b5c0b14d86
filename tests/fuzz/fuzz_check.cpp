// Finding report and input hash of the fuzz targets (see fuzz_check.h).
#include "fuzz_check.h"

#include <cstdio>
#include <cstdlib>
#include <string>

namespace ncinterp::fuzz {

void fail(const std::string& what) {
  std::fprintf(stderr, "FUZZ FINDING: %s\n", what.c_str());
  std::fflush(stderr);
  std::abort();
}

bool injected(const char* fault) {
  static const char* const name = std::getenv("NCINTERP_FUZZ_INJECT");
  return name != nullptr && std::string(name) == fault;
}

uint64_t input_hash(const uint8_t* data, size_t size) {
  uint64_t h = 1469598103934665603ull;
  for (size_t i = 0; i < size; ++i) h = (h ^ data[i]) * 1099511628211ull;
  return h;
}

}  // namespace ncinterp::fuzz
