// Sweep test support (see sweep_test_support.h).
#include "sweep_test_support.h"

#include "subprocess.h"

namespace ncinterp::sweep::test {

std::string example(const std::string& name) { return std::string(NCINTERP_EXAMPLES_DIR) + "/" + name; }

std::string fixture(const std::string& name) {
  return std::string(NCINTERP_SWEEP_TEST_DIR) + "/fixtures/" + name;
}

std::string log_snippet(const std::string& name) {
  return read_text_file(std::string(NCINTERP_SWEEP_TEST_DIR) + "/logs/" + name);
}

}  // namespace ncinterp::sweep::test
