// Running the external tools of the sweep (yosys, nextpnr-ice40, cmake, a verilated
// variant) as child processes, their output into a log file.
// Idea: a tool that is missing, fails or dies must become a reason in the sweep's table,
// never an exception that ends the sweep; so every outcome is a value: not found, could not
// start, killed by a signal, or an exit code, with the log kept for the reason's details.
// posix_spawn is safe to call from the sweep's worker threads.
#pragma once
#include <optional>
#include <string>
#include <vector>

namespace ncinterp::sweep {

struct ProcessOutcome {
  bool started = false;
  int exit_code = -1;      // when it exited
  int signal = 0;          // when a signal ended it
  std::string failure;     // why it did not start or did not exit normally; empty otherwise
  bool ok() const { return started && signal == 0 && exit_code == 0; }
};

// Full path of an executable: `name` itself if it contains '/', else the first match on
// $PATH. nullopt when there is none.
std::optional<std::string> find_executable(const std::string& name);

// Runs argv (argv[0] resolved with find_executable) with stdin from /dev/null and stdout
// and stderr into log_path (created or truncated). Waits for it to end.
ProcessOutcome run_process(const std::vector<std::string>& argv, const std::string& log_path);

// The whole file, or "" when it cannot be read.
std::string read_text_file(const std::string& path);

}  // namespace ncinterp::sweep
