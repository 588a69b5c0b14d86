// The interpolator's ports as SystemC signals, for the golden engine's VCD (engine.h).
// Idea: SystemC's tracer records signals, so while a VCD window is open the system drives
// these signals every half clock (system_top.cpp): the clock, reset and the tape reader's
// inputs, and the outputs (interp_outputs.def) with the C++ types of the verilated ports.
// Outside a window nobody writes them: the engines are stepped as plain C++.
#pragma once
#include <systemc>

#include "interp_ports.h"

namespace ncinterp::system {

struct WaveSignals {
  sc_core::sc_signal<bool> clk_i{"clk_i"};
  sc_core::sc_signal<bool> rst_ni{"rst_ni"};
  sc_core::sc_signal<uint64_t> feed_modulus_i{"feed_modulus_i"};
  sc_core::sc_signal<uint32_t> frame_i{"frame_i"};
  sc_core::sc_signal<bool> frame_valid_i{"frame_valid_i"};
  sc_core::sc_signal<bool> tape_end_i{"tape_end_i"};
#define INTERP_OUTPUT(name, kind, width) \
  sc_core::sc_signal<Port##kind::Signal> name##_o{#name "_o"};
#include "interp_outputs.def"
#undef INTERP_OUTPUT

  // The outputs of an edge, as the verilated ports would show them.
  void write_outputs(const InterpOutputs& o, const InterpConfig& cfg) {
#define INTERP_OUTPUT(name, kind, width) name##_o.write(Port##kind::to_signal(o.name, width));
#include "interp_outputs.def"
#undef INTERP_OUTPUT
  }
  // The inputs the next edge will see.
  void write_inputs(const InterpInputs& in) {
    frame_i.write(in.frame);
    frame_valid_i.write(in.frame_valid);
    tape_end_i.write(in.tape_end);
  }
};

}  // namespace ncinterp::system
