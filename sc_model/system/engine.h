// An interpolator engine of the system model: the golden model or the verilated RTL, clocked
// as plain C++ by the system's one process (system_top.h), with its own VCD tracer.
// Idea: SystemC's scheduler costs more per clock than the design itself (several process
// activations and a signal update per port per clock, docs/performance.md), so the engine
// is not a SystemC module with ports: the system steps it directly, and only a VCD window
// runs clock by clock in SystemC time. Both engines write VCD with their own simulator's
// tracer (SystemC's sc_trace over the system's wave signals for the golden model,
// Verilator's VerilatedVcdC for the RTL) under the same names: SystemC's tracer puts
// everything under a root scope "SystemC", the golden engine's ports are traced as
// "interp.interp_top.<port>" with the RTL's bit widths, and the verilated model is named
// "SystemC.interp" (verilated_interp.h). Full names are SystemC.interp.interp_top.<port>
// in both files (the RTL's file also has its internals).
#pragma once
#include <memory>
#include <string>

#include "interp_ports.h"

namespace ncinterp::system {

struct WaveSignals;  // interp_signals.h

class Engine {
 public:
  virtual ~Engine() = default;
  // The reset edge (cycle 0): one edge with rst_ni low.
  virtual void reset() = 0;
  // One rising edge with these inputs (those before the edge).
  virtual void tick(const InterpInputs& in) = 0;
  // The outputs after the last edge.
  virtual const InterpOutputs& outputs() const = 0;
  // Event jumping (GoldenInterp::quiet_ticks): how many next edges with `in` held change
  // nothing but internal counters, and skip(n) for n of them. An engine that cannot tell
  // says 0 (the verilated RTL: it is clocked every edge).
  virtual uint64_t quiet_ticks(const InterpInputs&) const { return 0; }
  virtual void skip(uint64_t) {}
  // Starts writing a VCD to `path` now, half a clock before the next edge; every edge from
  // then on is in it. The golden engine traces the system's wave signals, which the system
  // drives clock by clock while a VCD is open.
  virtual void open_vcd(const std::string& path) = 0;
  // Flushes and closes the VCD (no-op when none is open).
  virtual void close_vcd() = 0;
};

std::unique_ptr<Engine> make_golden_engine(const InterpConfig& cfg, const WaveSignals& waves);
// `with_trace`: the trace-enabled verilated model (needed by open_vcd; a little slower).
// The RTL is verilated with the default widths: throws std::runtime_error for others.
std::unique_ptr<Engine> make_rtl_engine(const InterpConfig& cfg, double clock_hz, bool with_trace);

}  // namespace ncinterp::system
