// `ncinterp bitstream --board icestick|icebreaker -o X.bin [--work-dir D]`: the board's
// bitstream from the repository's RTL (rtl/board/board_top.sv and the interpolator) and
// .pcf (sw/tools/bitstream/bitstream.h). Prints the logic cells used and the Fmax against the
// board clock. Exit (README, "Exit codes"): 0 built; 2 the design does not fit or misses the
// board clock; 4 a tool failed (the tools' logs stay in the work directory); 1 usage or an
// output that cannot be written, found before any tool runs.
#include <cstdio>
#include <filesystem>
#include <iostream>

#include "bitstream.h"
#include "command_registry.h"
#include "output_set.h"

namespace ncinterp::cli {
namespace {

struct BitstreamArgs {
  std::string board, out, work_dir;
  unsigned seeds = 5;
};

int run(const BitstreamArgs& a) {
  const bitstream::BoardTarget target = bitstream::board_target(a.board);
  OutputSet outputs;
  AtomicOutputFile* bin = outputs.add(a.out);
  const std::string work =
      a.work_dir.empty() ? std::filesystem::path(a.out).string() + ".build" : a.work_dir;
  const bitstream::BitstreamResult r = bitstream::build_bitstream(target, bin->temp_path(), work, a.seeds);
  if (!r.ok()) {
    std::cerr << "ncinterp bitstream: " << r.message << "\n";
    return r.failure == bitstream::BitstreamResult::Failure::kDesign ? 2 : 4;
  }
  outputs.commit();
  std::printf("%s\nbitstream: %s (logs in %s)\n", r.message.c_str(), a.out.c_str(), r.work_dir.c_str());
  return 0;
}

void setup(CLI::App& app) {
  auto args = std::make_shared<BitstreamArgs>();
  CLI::App* cmd = app.add_subcommand("bitstream", "Build a board's bitstream (yosys, nextpnr-ice40, icepack)");
  cmd->add_option("--board", args->board, "Board: icestick (HX1K, the lines-only core) or icebreaker (UP5K)")
      ->check(CLI::IsMember({"icestick", "icebreaker"}))
      ->required();
  cmd->add_option("-o,--output", args->out, "Bitstream file (.bin, for iceprog)")->required();
  cmd->add_option("--seeds", args->seeds, "Placement seeds to try until one meets the board clock")
      ->check(CLI::Range(1u, 100u))
      ->capture_default_str();
  cmd->add_option("--work-dir", args->work_dir, "Netlists and tool logs (default: OUTPUT.build)");
  cmd->callback([args] { run_command("bitstream", [&] { return run(*args); }); });
}

const CommandRegistration registration("bitstream", setup);

}  // namespace
}  // namespace ncinterp::cli
