// Command-line tests of the ncinterp executable: the executable run with its stdout and
// stderr captured, in a test with a scratch directory.
// Idea: the captures go beside the directory, not into it, so a test can check exactly
// which files a command left behind (nothing, on bad input). The executable's path comes
// from the test target's NCINTERP_BINARY definition, the examples' folder from
// NCINTERP_EXAMPLES_DIR.
#pragma once
#include <sys/wait.h>

#include <cstdlib>
#include <filesystem>
#include <string>

#include "scratch_dir_test.h"

namespace ncinterp::test {

// examples/<name> in the source tree.
inline std::string example(const std::string& name) {
  return std::string(NCINTERP_EXAMPLES_DIR) + "/" + name;
}

class CliTest : public ScratchDirTest {
 protected:
  // Runs `ncinterp ARGS`; returns its exit status and keeps its output in stdout_/stderr_.
  int run(const std::string& args) {
    const std::string base = dir_.string();
    const std::string cmd =
        std::string(NCINTERP_BINARY) + " " + args + " >" + base + ".out 2>" + base + ".err";
    const int status = std::system(cmd.c_str());
    stdout_ = slurp(base + ".out");
    stderr_ = slurp(base + ".err");
    std::filesystem::remove(base + ".out");
    std::filesystem::remove(base + ".err");
    return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  }

  std::string stdout_, stderr_;
};

}  // namespace ncinterp::test
