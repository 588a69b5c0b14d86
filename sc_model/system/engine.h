// An interpolator engine in the system model: the golden model or the verilated RTL,
// bound to the system's signals, with its own VCD tracer.
// Idea: both engines write VCD with their own simulator's tracer (SystemC's sc_trace for
// the golden model, Verilator's VerilatedVcdSc for the RTL) and both files name the ports
// identically: SystemC's tracer puts everything under a root scope "SystemC", so the
// system's top module is named "SystemC" and the engine instance "interp"; Verilator then
// scopes the RTL as "SystemC.interp" / "interp_top", and the golden engine's ports are
// traced as "interp.interp_top.<port>" with the RTL's bit widths. Full names are
// SystemC.interp.interp_top.<port> in both files (the RTL's file also has its internals).
#pragma once
#include <memory>
#include <string>

#include <systemc>

#include "interp_ports.h"
#include "interp_signals.h"

namespace ncinterp::system {

class Engine {
 public:
  virtual ~Engine() = default;
  // Starts writing a VCD to `path` now (during the simulation, at a clock's falling edge);
  // the first values dumped are the signals' current values.
  virtual void open_vcd(const std::string& path) = 0;
  // Flushes and closes the VCD (no-op when none is open).
  virtual void close_vcd() = 0;
};

// The engine instance is created as a child of the current module (name "interp").
std::unique_ptr<Engine> make_golden_engine(const InterpConfig& cfg,
                                           sc_core::sc_signal_in_if<bool>& clk,
                                           InterpSignals& signals);
// Throws std::runtime_error when this build has no verilated SystemC RTL (ncinterp_rtl_sc).
// `with_trace` must be true for open_vcd to work (Verilator's traceEverOn).
std::unique_ptr<Engine> make_rtl_engine(const InterpConfig& cfg,
                                        sc_core::sc_signal_in_if<bool>& clk,
                                        InterpSignals& signals, bool with_trace);
bool rtl_engine_available();

}  // namespace ncinterp::system
