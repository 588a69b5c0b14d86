// Hardware cost of the interpolator RTL at one increment-register width W: yosys generic
// synthesis (cells, flip-flops), yosys synth_ice40 (LUTs), nextpnr-ice40 on an HX8K
// (placed logic cells, Fmax).
// Idea: every number comes from a tool run at that W (`chparam -set IncWidth W`); a tool
// that is missing or fails leaves its columns empty with the reason (first error line of
// its log, kept in the work directory). interp_top has more ports than the HX8K's CT256
// package has pins, so placement and Fmax use the harness interp_fpga_top.sv, which adds
// only edge registers; the LUT count is interp_top's own.
#pragma once
#include <string>
#include <utility>
#include <vector>

#include "sweep_row.h"

namespace ncinterp::sweep {

struct SynthesisSetup {
  std::vector<std::string> rtl_sources;  // interp_top and its modules (rtl/CMakeLists.txt)
  std::string fpga_top;                  // interp_fpga_top.sv
  std::string yosys = "yosys";
  std::string nextpnr = "nextpnr-ice40";
  // Options of every synth_ice40 run (rtl/fpga/synth_ice40.options); empty: yosys's defaults.
  std::string synth_ice40_options;
  std::string work_dir;                  // logs and netlists go to <work_dir>/w<W>/
  std::string cache_dir;                 // results per (hash, W); empty: no cache
  // The part nextpnr-ice40 places on: the HX8K in its CT256 package, 7680 logic cells.
  std::string pnr_part_name = "HX8K";
  std::vector<std::string> pnr_part_args = {"--hx8k", "--package", "ct256"};
  // A second, small part placed as well (the HX1K in its TQ144 package, 1280 logic
  // cells); an empty name: not placed.
  std::string small_part_name = "HX1K";
  std::vector<std::string> small_part_args = {"--hx1k", "--package", "tq144"};
  double pnr_target_mhz = 50.0;          // nextpnr's timing target (--freq)
  unsigned pnr_seed = 1;                 // placement seed, fixed so reruns agree
};

// The cache key of this setup: RTL and harness contents, commands, tool versions.
std::string synthesis_key(const SynthesisSetup& setup);

// RTL parameters of one hardware point, in a fixed order: name -> value, each set with
// `chparam -set NAME VALUE` on interp_top and on the harness.
using RtlParameters = std::vector<std::pair<std::string, long long>>;

// Synthesises (or takes from the cache under `key`) the RTL with these parameters. Never
// throws for a tool failure: each value is measured or carries its reason.
SynthResult synthesize(const RtlParameters& params, const SynthesisSetup& setup, const std::string& key);
// The same at IncWidth = W, every other parameter at its default.
SynthResult synthesize(unsigned width, const SynthesisSetup& setup, const std::string& key);
// The cache and work-directory tag of a parameter set: "w12", "w12-FeedWidth24".
std::string parameter_tag(const RtlParameters& params);

}  // namespace ncinterp::sweep
