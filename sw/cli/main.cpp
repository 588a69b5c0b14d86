// ncinterp command-line entry point: builds the CLI11 app from the registered subcommands
// (see command_registry.h) and maps failures to exit codes. Commands print their own
// one-line error to stderr ("FILE: block N, offset K: message") and throw CommandExit.
#include <algorithm>
#include <exception>
#include <iostream>

#include "command_registry.h"

int main(int argc, char** argv) {
  using namespace ncinterp::cli;
  CLI::App app{"ncinterp: two-stage NC interpolator (first stage, golden model, RTL)"};
  app.require_subcommand(1);
  auto& entries = command_registry();
  std::sort(entries.begin(), entries.end(),
            [](const CommandEntry& a, const CommandEntry& b) { return a.name < b.name; });
  for (auto& entry : entries) entry.setup(app);
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    return app.exit(e);
  } catch (const CommandExit& e) {
    return e.code;
  } catch (const std::exception& e) {
    std::cerr << "ncinterp: " << e.what() << "\n";
    return 1;
  }
  return 0;
}
