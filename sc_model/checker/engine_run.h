// Runs an interpolator engine clock by clock from a FrameSource and hands the outputs of
// every clock to an observer (the checker).
// Idea: the golden model and the verilated RTL harness have the same reset()/tick()/
// outputs() shape, so one template drives either, with no SystemC and no virtual call on
// the per-clock path. The run stops at done, at error, or at max_cycles.
#pragma once
#include <cstdint>

#include "frame_source.h"
#include "interp_ports.h"

namespace ncinterp::checker {

struct RunEnd {
  uint64_t cycles = 0;
  bool done = false;
  bool error = false;
  bool timed_out = false;  // max_cycles reached first
};

template <class Engine, class Observer>
RunEnd run_engine(Engine& engine, FrameSource& source, uint64_t max_cycles, Observer&& observe) {
  engine.reset();
  observe(uint64_t{0}, engine.outputs());
  RunEnd end;
  for (uint64_t cycle = 1; cycle <= max_cycles; ++cycle) {
    const bool ready = engine.outputs().frame_ready;
    engine.tick(source.inputs());
    source.clock(ready);
    const InterpOutputs& o = engine.outputs();
    observe(cycle, o);
    end.cycles = cycle;
    if (o.done || o.error) {
      end.done = o.done;
      end.error = o.error;
      return end;
    }
  }
  end.timed_out = true;
  return end;
}

}  // namespace ncinterp::checker
