// This build's sweep setup (see sweep_defaults.h).
#include "sweep_defaults.h"

#include <algorithm>
#include <filesystem>
#include <iterator>

#include "sweep_build_paths.h"

namespace ncinterp::sweep {
namespace {

std::string or_default(const std::string& dir) { return dir.empty() ? std::string(build::kCacheDir) : dir; }

}  // namespace

std::string default_cache_dir() { return build::kCacheDir; }

std::string default_tape_dir(const std::string& cache_dir) { return or_default(cache_dir) + "/tapes"; }

SynthesisSetup default_synthesis_setup(const std::string& cache_dir) {
  SynthesisSetup s;
  s.rtl_sources.assign(std::begin(build::kRtlSources), std::end(build::kRtlSources));
  s.fpga_top = std::string(build::kSweepSourceDir) + "/interp_fpga_top.sv";
  s.synth_ice40_options = build::kSynthIce40Options;
  s.cache_dir = or_default(cache_dir) + "/synth";
  s.work_dir = or_default(cache_dir) + "/work";
  return s;
}

RtlVariantSetup default_rtl_variant_setup(const std::string& cache_dir) {
  RtlVariantSetup s;
  s.project_dir = std::string(build::kSweepSourceDir) + "/rtl_variant";
  s.source_dir = build::kSourceDir;
  s.rtl_sources.assign(std::begin(build::kRtlSources), std::end(build::kRtlSources));
  s.verilator_args.assign(std::begin(build::kVerilatorArgs), std::end(build::kVerilatorArgs));
  s.golden_library = build::kGoldenLibrary;
  s.cmake = build::kCmake;
  s.generator = build::kGenerator;
  s.cxx_compiler = build::kCxxCompiler;
  s.build_root = or_default(cache_dir) + "/rtl";
  return s;
}

std::vector<std::string> model_source_files() {
  std::vector<std::string> files;
  const std::string root = build::kSourceDir;
  for (const char* dir : {"sw/host/firststage", "sw/host/tape", "sc_model/golden", "sc_model/checker", "sw/tools/sweep"})
    for (const auto& e : std::filesystem::recursive_directory_iterator(root + "/" + dir)) {
      const std::string ext = e.path().extension().string();
      if (e.is_regular_file() && (ext == ".h" || ext == ".cpp" || ext == ".sv" || ext == ".def")) files.push_back(e.path().string());
    }
  std::sort(files.begin(), files.end());
  return files;
}

}  // namespace ncinterp::sweep
