// The options that choose the machine a command plays on, one definition each, for every
// command that plays a tape (play, cosim, check, board-sim, sweep's grid and the soak read
// the same words): --arch.
// Idea: a user learns an option once; its name, values, default and help are written here
// only, and a command adds it with one call.
#pragma once
#include <CLI/CLI.hpp>
#include <map>
#include <string>

#include "interp_ports.h"

namespace ncinterp::cli {

// --arch serial|parallel into `arch` (default: serial, what the boards ship).
inline CLI::Option* add_arch_option(CLI::App* cmd, Arch& arch) {
  static const std::map<std::string, Arch> kArchs = {{"serial", Arch::kSerial},
                                                     {"parallel", Arch::kParallel}};
  return cmd
      ->add_option("--arch", arch,
                   "Interpolator microarchitecture, for the golden model and the RTL alike: "
                   "serial (bit-serial DDA, 2P clocks per iteration: what the boards ship) or "
                   "parallel (one DDA iteration per clock)")
      ->transform(CLI::CheckedTransformer(kArchs))
      ->default_str(arch_name(arch));
}

}  // namespace ncinterp::cli
