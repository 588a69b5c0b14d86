// The bit-width sweep: for every W of the range, the tapes, errors, feed and cycles of
// every input (first stage + golden model + checker), the hardware cost (yosys, nextpnr)
// and the RTL variant in lock step with the golden model.
// Idea: widths are independent, so a pool of `jobs` threads takes them one at a time
// (synthesis and the variant builds are child processes, the rest runs in the thread);
// whatever fails at one width becomes that row's reason and the sweep goes on.
#pragma once
#include <cstddef>
#include <functional>
#include <string>
#include <vector>

#include "rtl_variant.h"
#include "sweep_row.h"
#include "synthesis.h"
#include "tape_measurement.h"
#include "width_range.h"

namespace ncinterp::sweep {

struct SweepSetup {
  WidthRange widths;
  std::vector<SweepInput> inputs;
  MeasureSetup measure;
  unsigned jobs = 0;          // 0: one per core
  bool synthesis = true;      // yosys + nextpnr columns
  SynthesisSetup synth;
  bool rtl = true;            // the verilated variant in lock step
  RtlVariantSetup rtl_variant;
  std::string tape_dir;       // tapes for the RTL variant: <tape_dir>/w<W>/
};

struct SweepProgress {
  unsigned width = 0;
  std::string stage;          // what that width is doing now ("done" when finished)
  size_t widths_done = 0, widths_total = 0;
};
using ProgressCallback = std::function<void(const SweepProgress&)>;

// One row per width, in width order. progress (optional) is called from the worker
// threads, one call at a time.
std::vector<SweepRow> run_sweep(const SweepSetup& setup, const ProgressCallback& progress = nullptr);

}  // namespace ncinterp::sweep
