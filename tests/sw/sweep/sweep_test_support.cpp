// Sweep test support (see sweep_test_support.h).
#include "sweep_test_support.h"

#include <gtest/gtest.h>
#include <sys/wait.h>

#include <cstdio>
#include <filesystem>

#include "subprocess.h"

namespace ncinterp::sweep::test {

std::string example(const std::string& name) { return std::string(NCINTERP_EXAMPLES_DIR) + "/" + name; }

std::string fixture(const std::string& name) {
  return std::string(NCINTERP_SWEEP_TEST_DIR) + "/fixtures/" + name;
}

std::string log_snippet(const std::string& name) {
  return read_text_file(std::string(NCINTERP_SWEEP_TEST_DIR) + "/logs/" + name);
}

std::string fresh_dir() {
  const ::testing::TestInfo* t = ::testing::UnitTest::GetInstance()->current_test_info();
  const std::string dir = std::string(NCINTERP_SWEEP_TEST_WORK) + "/" + t->test_suite_name() + "." + t->name();
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  return dir;
}

CommandResult run_ncinterp(const std::string& args, const std::string& env_prefix) {
  const std::string cmd = env_prefix + std::string(NCINTERP_BINARY) + " " + args + " 2>&1";
  CommandResult r;
  FILE* p = ::popen(cmd.c_str(), "r");
  if (!p) return r;
  char buf[4096];
  for (size_t n; (n = std::fread(buf, 1, sizeof buf, p)) > 0;) r.output.append(buf, n);
  const int status = ::pclose(p);
  r.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  return r;
}

}  // namespace ncinterp::sweep::test
