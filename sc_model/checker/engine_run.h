// Runs an interpolator engine clock by clock from a FrameSource and hands the outputs of
// every clock to an observer (the checker).
// Idea: the golden model and the verilated RTL harness have the same reset()/tick()/
// outputs() shape, so one template drives either, with no SystemC and no virtual call on
// the per-clock path. The run stops at done, at error, at a pause no press resumes
// (FrameSource::run_over), or at max_cycles.
// No output struct is copied per clock: the golden model's is observed in place, and the
// verilated model's ports are read field by field into one struct (read_outputs). A copy
// of the whole struct right after its fields were stored one by one stalls on store
// forwarding (docs/performance.md).
#pragma once
#include <algorithm>
#include <cstdint>

#include "frame_source.h"
#include "interp_ports.h"

namespace ncinterp {
template <class Model>
class VerilatedInterp;  // verilated_interp.h, included where the RTL engine is built
}  // namespace ncinterp

namespace ncinterp::checker {

struct RunEnd {
  uint64_t cycles = 0;
  InterpOutputs last;  // the outputs after the last clock run: done, error, paused, or
                       // none of them (max_cycles reached first)
};

// The engine's outputs after its last clock: the golden model's in place; the verilated
// model's ports read into `into`.
template <class Engine>
const InterpOutputs& current_outputs(const Engine& engine, InterpOutputs&) {
  return engine.outputs();
}
template <class Model>
const InterpOutputs& current_outputs(const VerilatedInterp<Model>& engine, InterpOutputs& into) {
  engine.read_outputs(into);
  return into;
}

template <class Engine, class Observer>
RunEnd run_engine(Engine& engine, FrameSource& source, uint64_t max_cycles, Observer&& observe) {
  InterpOutputs read;
  engine.reset();
  const InterpOutputs* last = &current_outputs(engine, read);
  observe(uint64_t{0}, *last);
  RunEnd end;
  for (uint64_t cycle = 1; cycle <= max_cycles && !source.run_over(*last); ++cycle) {
    const bool ready = last->frame_ready;
    engine.tick(source.inputs());
    source.clock(ready);
    last = &current_outputs(engine, read);
    observe(cycle, *last);
    end.cycles = cycle;
  }
  end.last = *last;
  return end;
}

// After a run that a stop (E-stop, a limit) ended: `clocks` more clocks of the engine and
// its source, each clock's outputs to observe (from_cycle + 1 on), so that a pulse the stop
// should have muted shows. The run's end stays the stop's.
template <class Engine, class Observer>
void run_past_stop(Engine& engine, FrameSource& source, uint64_t from_cycle, uint64_t clocks,
                   Observer&& observe) {
  InterpOutputs read;
  for (uint64_t k = 1; k <= clocks; ++k) {
    const bool ready = current_outputs(engine, read).frame_ready;
    engine.tick(source.inputs());
    source.clock(ready);
    observe(from_cycle + k, current_outputs(engine, read));
  }
}

// The golden model with event jumping: where the model, the reader and the observer all
// allow it (GoldenInterp::quiet_ticks, FrameSource::steady_clocks, checker.quiet_limit()),
// the quiet clocks are passed in one step and reported to checker.observe_quiet(); every
// other clock is ticked and observed as run_engine() does. The same outputs at every
// clock as run_engine() (tests/sc_model/golden: JumpedRunEqualsClocked).
template <class Golden, class Checker, class Observer>
RunEnd run_engine_jumping(Golden& engine, FrameSource& source, uint64_t max_cycles, Checker& checker,
                          Observer&& observe) {
  engine.reset();
  const InterpOutputs* last = &engine.outputs();
  observe(uint64_t{0}, *last);
  RunEnd end;
  for (uint64_t cycle = 1; cycle <= max_cycles && !source.run_over(*last);) {
    const InterpInputs in = source.inputs();
    uint64_t n = engine.quiet_ticks(in);
    if (n > 0) {
      const uint64_t limit = checker.quiet_limit();
      n = std::min({n, source.steady_clocks(), max_cycles - cycle + 1,
                    limit >= cycle ? limit - cycle + 1 : uint64_t{0}});
    }
    if (n > 0) {
      engine.skip(n);
      source.skip(n);
      cycle += n;
      checker.observe_quiet(cycle - 1, *last);
      end.cycles = cycle - 1;
      continue;
    }
    const bool ready = last->frame_ready;
    engine.tick(in);
    source.clock(ready);
    last = &engine.outputs();
    observe(cycle, *last);
    end.cycles = cycle++;
  }
  end.last = *last;
  return end;
}

}  // namespace ncinterp::checker
