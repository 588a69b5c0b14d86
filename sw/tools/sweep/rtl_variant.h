// The RTL at width W, verilated with -GIncWidth=W, in lock step with the golden model at
// W on the sweep's tapes: one command builds the variant (if needed) and runs it.
// Idea: each variant is its own small CMake build (sw/tools/sweep/rtl_variant/) in the cache,
// configured with the main build's RTL source list, Verilator flags and golden-model
// library, so CMake rebuilds it only when something it depends on changed. The lock-step
// scoreboard compares every output on every clock: when it reports a match, the checker's
// measurements of the golden model at W hold for the RTL at W as well.
#pragma once
#include <string>
#include <vector>

#include "sweep_row.h"

namespace ncinterp::sweep {

struct RtlVariantSetup {
  std::string project_dir;                  // sw/tools/sweep/rtl_variant
  std::string source_dir;                   // the project's source tree
  std::vector<std::string> rtl_sources;     // as rtl/CMakeLists.txt lists them
  std::vector<std::string> verilator_args;  // as rtl/CMakeLists.txt passes them
  std::string golden_library;               // the main build's libncinterp_golden.a
  std::string cmake = "cmake";
  std::string generator;                    // CMake generator ("" = CMake's default)
  std::string cxx_compiler;                 // "" = CMake's default
  std::string build_root;                   // variant build trees: <build_root>/w<W>[-serial]
  bool bit_serial = false;              // BitSerial = 1 (interp_top's parameter)
  double clock_hz = 1e6;
  double reader_cps = 1000.0;
};

// Path of the variant's executable once built.
std::string rtl_variant_executable(const RtlVariantSetup& setup, unsigned width);
// Configures and builds the variant; "" on success, else the reason (with the log's path).
std::string build_rtl_variant(const RtlVariantSetup& setup, unsigned width);
// Builds the variant and runs the lock-step cosim on every tape. Never throws for a
// failed build or run: the result says why.
RtlResult run_rtl_variant(const RtlVariantSetup& setup, unsigned width, const std::vector<std::string>& tapes);

}  // namespace ncinterp::sweep
