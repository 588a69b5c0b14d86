// VCD of the RTL over a window of clocks, written with Verilator's own tracer.
// Idea: the RTL with its own FrameSource is deterministic, so re-running the trace-enabled
// model of the configured arch (rtl_models.h) from reset reproduces exactly the clocks of a lock-step run;
// only the window [first_cycle, last_cycle] is dumped, so a mismatch found after a billion
// clocks still gives a small file. Scopes and time base as the system model's VCDs
// (docs/waves.md): SystemC.interp.interp_top.<instance>.<signal>, 1 ps, edge c at
// (c + 1) clock periods.
#pragma once
#include <cstdint>
#include <string>
#include <vector>

#include "atomic_file.h"
#include "lockstep.h"

namespace ncinterp::cosim {

// Writes path atomically (AtomicOutputFile: temporary file + rename); clk_hz sets the
// period. Throws std::runtime_error on I/O failure.
void write_rtl_vcd(const std::vector<uint8_t>& frames, const Options& options, double clock_hz,
                   uint64_t first_cycle, uint64_t last_cycle, const std::string& path);
// The same into an output the caller reserved (an OutputSet) and commits.
void write_rtl_vcd(const std::vector<uint8_t>& frames, const Options& options, double clock_hz,
                   uint64_t first_cycle, uint64_t last_cycle, AtomicOutputFile& out);

}  // namespace ncinterp::cosim
