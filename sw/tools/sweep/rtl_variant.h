// The RTL with other parameters than the main build's models (a width W, a BLU, an arch,
// circle mode or not), verilated with -GIncWidth=W -GFracDigits=D -GBitSerial=B
// -GCircleMode=C, in lock step with the golden
// model configured alike on the sweep's or the soak's tapes: one command builds the variant
// (if needed) and runs it.
// Idea: each variant is its own small CMake build (sw/tools/sweep/rtl_variant/) in the cache,
// configured with the main build's RTL source list, Verilator flags and golden-model
// library, so CMake rebuilds it only when something it depends on changed. The lock-step
// scoreboard compares every output on every clock: when it reports a match, the checker's
// measurements of the golden model at W hold for the RTL at W as well.
#pragma once
#include <string>
#include <vector>

#include "interp_ports.h"
#include "sweep_row.h"

namespace ncinterp::sweep {

// The parameters a variant is built with (the others are the RTL's defaults).
struct RtlVariant {
  unsigned width = 16;       // IncWidth
  unsigned frac_digits = 3;  // FracDigits (BLU = 10^-frac_digits mm)
  Arch arch = Arch::kSerial;
  bool circle_mode = true;   // CircleMode (false: the lines-only core)
  // "W=16 D=3 serial" (" lines" without circle mode): in messages and the build tree's name.
  std::string name() const;
};

struct RtlVariantSetup {
  std::string project_dir;                  // sw/tools/sweep/rtl_variant
  std::string source_dir;                   // the project's source tree
  std::vector<std::string> rtl_sources;     // as rtl/CMakeLists.txt lists them
  std::vector<std::string> verilator_args;  // as rtl/CMakeLists.txt passes them
  std::string golden_library;               // the main build's libncinterp_golden.a
  std::string cmake = "cmake";
  std::string generator;                    // CMake generator ("" = CMake's default)
  std::string cxx_compiler;                 // "" = CMake's default
  std::string build_root;                   // variant build trees: <build_root>/w<W>-d<D>-<arch>
  double clock_hz = 1e6;
  double reader_cps = 1000.0;
};

// Path of the variant's executable once built.
std::string rtl_variant_executable(const RtlVariantSetup& setup, const RtlVariant& variant);
// Configures and builds the variant; "" on success, else the reason (with the log's path).
std::string build_rtl_variant(const RtlVariantSetup& setup, const RtlVariant& variant);
// Builds the variant and runs the lock-step cosim on every tape. Never throws for a
// failed build or run: the result says why (`lines`, if given, gets the variant's line per
// tape: "done CYCLES TAPE" or "mismatch|error|cycle_limit CYCLES TAPE: why").
RtlResult run_rtl_variant(const RtlVariantSetup& setup, const RtlVariant& variant,
                          const std::vector<std::string>& tapes,
                          std::vector<std::string>* lines = nullptr);

}  // namespace ncinterp::sweep
