// ncinterp command-line entry point: builds the CLI11 app from the registered subcommands
// (see command_registry.h) and maps failures to exit codes. Commands print their own
// one-line error to stderr ("FILE: block N, offset K: message") and throw CommandExit.
// One exit-code rule for every command (README.md, "Exit codes"): 0 ok, 1 bad input or
// usage (a CLI11 parse error too: one line, not CLI11's own codes 100+), 2 the check failed
// (check, cosim), 3 cycle limit reached (cosim).
#include <algorithm>
#include <exception>
#include <iostream>

#include "command_registry.h"

int main(int argc, char** argv) {
  using namespace ncinterp::cli;
  CLI::App app{"ncinterp: two-stage NC interpolator (first stage, golden model, RTL)"};
  app.require_subcommand(1);
  app.set_version_flag("--version", std::string("ncinterp ") + NCINTERP_VERSION);
  auto& entries = command_registry();
  std::sort(entries.begin(), entries.end(),
            [](const CommandEntry& a, const CommandEntry& b) { return a.name < b.name; });
  for (auto& entry : entries) entry.setup(app);
  try {
    app.parse(argc, argv);
  } catch (const CLI::CallForHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForAllHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForVersion& e) {
    return app.exit(e);
  } catch (const CLI::ParseError& e) {
    // Usage errors exit 1 like every other bad input, with one line.
    std::cerr << "ncinterp: " << e.what() << " (ncinterp --help, ncinterp COMMAND --help)\n";
    return 1;
  } catch (const CommandExit& e) {
    return e.code;
  } catch (const std::exception& e) {
    std::cerr << "ncinterp: " << e.what() << "\n";
    return 1;
  }
  return 0;
}
