// Registry of ncinterp subcommands.
// Idea: each subcommand lives in its own cmd_<name>.cpp and registers itself with a static
// CommandRegistration, so adding a command never touches main.cpp. A command's setup
// function adds its CLI11 subcommand and sets the callback that does the work; the callback
// returns the process exit code through CommandExit.
#pragma once
#include <CLI/CLI.hpp>
#include <functional>
#include <iostream>
#include <string>
#include <vector>

namespace ncinterp::cli {

// Thrown by a command callback to end the program with a given exit code after it has
// printed its own message (CLI11 callbacks cannot return a value).
struct CommandExit {
  int code;
};

// The body of a command callback: runs `body` (which returns the exit code); an exception
// is one line "ncinterp NAME: what" on stderr and exit 1. A non-zero code ends the program.
template <class Body>
void run_command(const char* name, Body body) {
  int code;
  try {
    code = body();
  } catch (const std::exception& e) {
    std::cerr << "ncinterp " << name << ": " << e.what() << "\n";
    code = 1;
  }
  if (code != 0) throw CommandExit{code};
}

using CommandSetup = std::function<void(CLI::App& app)>;

struct CommandEntry {
  std::string name;
  CommandSetup setup;
};

inline std::vector<CommandEntry>& command_registry() {
  static std::vector<CommandEntry> entries;
  return entries;
}

struct CommandRegistration {
  CommandRegistration(std::string name, CommandSetup setup) {
    command_registry().push_back({std::move(name), std::move(setup)});
  }
};

}  // namespace ncinterp::cli
