// The lock-step loop over any verilated interpolator harness (see lockstep.h).
// Idea: a template over the RTL harness, so one loop serves the arch models of this build
// (lockstep.cpp dispatches on the configuration's arch) and a sweep or soak variant's own
// model (sw/tools/sweep/rtl_variant/), and the per-clock compare is inlined.
#pragma once
#include <cstdint>
#include <vector>

#include "dda_serial.h"
#include "frame_source.h"
#include "lockstep.h"

namespace ncinterp::cosim {

template <class Rtl>
Result run_lockstep_on(Rtl& rtl, const std::vector<uint8_t>& frames, const Options& options,
                       const Observer& observer = nullptr) {
  constexpr uint64_t kProgressMask = (uint64_t{1} << 24) - 1;
  GoldenInterp golden(options.config);
  if (options.fault.kind != GoldenInterp::Fault::kNone) golden.inject(options.fault);
  FrameSource golden_source(frames, options.cycles_per_frame, options.events);
  FrameSource rtl_source(frames, options.cycles_per_frame, options.events);

  Result result;
  Stats& stats = result.stats;
  uint64_t cycle = 0, idle_run = 0, loads = 0;
  // A stop (E-stop, a limit) ends the run once no iteration can still be in flight: the
  // engines are compared for two serial iterations more, so a pulse after the stop shows.
  uint64_t stop_cycle = 0;
  const uint64_t stop_settle = SerialDda::stop_watch_clocks(options.config.inc_width);
  auto compare = [&]() {
    if (rtl.same_as(golden.outputs())) return true;
    Mismatch m = first_difference(golden.outputs(), rtl.outputs());
    m.cycle = cycle;
    m.block = golden.outputs().block_n;
    m.cycles_matched = cycle == 0 ? 0 : cycle - 1;
    result.mismatch = m;
    result.end = Result::End::kMismatch;
    return false;
  };
  if (observer) observer(0, golden.outputs());
  if (compare()) {
    for (;;) {
      const InterpOutputs& g = golden.outputs();
      if (g.error && is_stop_error(g.error_code) && stop_cycle == 0) stop_cycle = cycle;
      if (g.done || (g.error && (stop_cycle == 0 || cycle >= stop_cycle + stop_settle))) {
        result.end = g.done ? Result::End::kDone : Result::End::kTapeError;
        break;
      }
      if (g.paused && golden_source.run_over(g)) {  // no cycle start comes
        result.end = Result::End::kPaused;
        break;
      }
      if (cycle >= options.max_cycles) {
        result.end = Result::End::kCycleLimit;
        break;
      }
      const bool golden_ready = g.frame_ready, rtl_ready = rtl.frame_ready();
      golden.tick(golden_source.inputs());
      rtl.tick(rtl_source.inputs());
      golden_source.clock(golden_ready);
      rtl_source.clock(rtl_ready);
      ++cycle;
      // Statistics from the golden outputs (equal to the RTL's unless reported below).
      const InterpOutputs& o = golden.outputs();
      if (o.step_x) ++stats.pulses[0][o.dir_x ? 1 : 0];
      if (o.step_y) ++stats.pulses[1][o.dir_y ? 1 : 0];
      if (golden.blocks_loaded() != loads) {
        if (loads > 0) stats.gap_cycles += idle_run;
        loads = golden.blocks_loaded();
        if (o.feed_saturated) ++stats.saturated_blocks;
      }
      idle_run = o.busy ? 0 : idle_run + 1;
      if (observer) observer(cycle, o);
      if ((cycle & kProgressMask) == 0 && options.progress) options.progress(cycle);
      if (!compare()) break;
    }
  }
  stats.blocks = loads;
  result.cycles = stop_cycle ? stop_cycle : cycle;  // a stopped run's: the stop's clock
  result.last = golden.outputs();
  return result;
}


}  // namespace ncinterp::cosim
