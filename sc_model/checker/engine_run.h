// Runs an interpolator engine clock by clock from a FrameSource and hands the outputs of
// every clock to an observer (the checker).
// Idea: the golden model and the verilated RTL harness have the same reset()/tick()/
// outputs() shape, so one template drives either, with no SystemC and no virtual call on
// the per-clock path. The run stops at done, at error, or at max_cycles.
// No output struct is copied per clock: the golden model's is observed in place, and the
// verilated model's ports are read field by field into one struct (read_outputs). A copy
// of the whole struct right after its fields were stored one by one stalls on store
// forwarding (docs/performance.md).
#pragma once
#include <cstdint>
#include <type_traits>
#include <utility>

#include "frame_source.h"
#include "interp_ports.h"

namespace ncinterp::checker {

struct RunEnd {
  uint64_t cycles = 0;
  bool done = false;
  bool error = false;
  bool timed_out = false;  // max_cycles reached first
  InterpOutputs last;      // the outputs of the last clock run
};

// The engine's outputs after its last clock: in place if it keeps them (GoldenInterp),
// else read into `into` (VerilatedInterp::read_outputs).
template <class Engine, class = void>
struct ReadsOutputs : std::false_type {};
template <class Engine>
struct ReadsOutputs<Engine, std::void_t<decltype(std::declval<const Engine&>().read_outputs(
                                std::declval<InterpOutputs&>()))>> : std::true_type {};

template <class Engine>
const InterpOutputs& current_outputs(const Engine& engine, InterpOutputs& into) {
  if constexpr (ReadsOutputs<Engine>::value) {
    engine.read_outputs(into);
    return into;
  } else {
    return engine.outputs();
  }
}

template <class Engine, class Observer>
RunEnd run_engine(Engine& engine, FrameSource& source, uint64_t max_cycles, Observer&& observe) {
  InterpOutputs read;
  engine.reset();
  const InterpOutputs* last = &current_outputs(engine, read);
  observe(uint64_t{0}, *last);
  RunEnd end;
  for (uint64_t cycle = 1; cycle <= max_cycles && !last->done && !last->error; ++cycle) {
    const bool ready = last->frame_ready;
    engine.tick(source.inputs());
    source.clock(ready);
    last = &current_outputs(engine, read);
    observe(cycle, *last);
    end.cycles = cycle;
  }
  end.done = last->done;
  end.error = last->error;
  end.timed_out = !end.done && !end.error;
  end.last = *last;
  return end;
}

}  // namespace ncinterp::checker
