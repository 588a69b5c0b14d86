// The sweep's setup for this build: the RTL files, the place-and-route harness, the
// variant project, the golden library and the cache directory under the build directory.
// Idea: CMake knows where everything is (sweep_build_paths.h is generated from the same
// lists the main build uses); the command and the tests start from these and override
// what they need (a cache directory, a tool that is not on PATH, a broken RTL file).
#pragma once
#include <string>
#include <vector>

#include "rtl_variant.h"
#include "synthesis.h"

namespace ncinterp::sweep {

// <build>/sweep-cache: plans, point results, synthesis cache, work files.
std::string default_cache_dir();
// cache_dir: "" = the build's own (<build>/sweep-cache). Synthesis results go to
// <cache_dir>/synth, logs and netlists to <cache_dir>/work.
SynthesisSetup default_synthesis_setup(const std::string& cache_dir = "");
// Variant build trees go to <cache_dir>/rtl.
RtlVariantSetup default_rtl_variant_setup(const std::string& cache_dir = "");
// The tapes the variants play: <cache_dir>/tapes.
std::string default_tape_dir(const std::string& cache_dir = "");
// The sources a point's measurement depends on besides the RTL (the first stage, the tape
// code, the golden model, the checker, the sweep itself): hashed into every point's key,
// so a result made by other code is never reused. Sorted, so every machine lists the same.
std::vector<std::string> model_source_files();

}  // namespace ncinterp::sweep
