// Shared by the sweep tests: paths of the examples and fixtures, a fresh work directory
// per test, and running the ncinterp binary.
#pragma once
#include <string>

namespace ncinterp::sweep::test {

std::string example(const std::string& name);   // examples/<name>
std::string fixture(const std::string& name);   // tests/sw/sweep/fixtures/<name>
std::string log_snippet(const std::string& name);  // the content of tests/sw/sweep/logs/<name>
// An empty directory for the running test (under the build tree), named after it.
std::string fresh_dir();

struct CommandResult {
  int exit_code = -1;
  std::string output;  // stdout and stderr
};
// Runs `ncinterp ARGS` through the shell (env_prefix, e.g. "PATH=/x ", goes before it).
CommandResult run_ncinterp(const std::string& args, const std::string& env_prefix = "");

}  // namespace ncinterp::sweep::test
