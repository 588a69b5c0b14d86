// The signals around the interpolator in the system model, named after its ports, and the
// one function that binds an engine to them.
// Idea: the golden SystemC module and the verilated RTL (Vinterp_top) have the same port
// names and C++ port types, so one template binds either; the reader and the monitor only
// ever see these signals.
#pragma once
#include <systemc>

#include "interp_ports.h"

namespace ncinterp::system {

struct InterpSignals {
  sc_core::sc_signal<bool> rst_ni{"rst_ni"};
  sc_core::sc_signal<uint64_t> feed_modulus_i{"feed_modulus_i"};
  sc_core::sc_signal<uint32_t> frame_i{"frame_i"};
  sc_core::sc_signal<bool> frame_valid_i{"frame_valid_i"};
  sc_core::sc_signal<bool> tape_end_i{"tape_end_i"};
  // The outputs (interp_outputs.def), named like the RTL's ports.
#define INTERP_OUTPUT(name, kind, width) \
  sc_core::sc_signal<Port##kind::Signal> name##_o{#name "_o"};
#include "interp_outputs.def"
#undef INTERP_OUTPUT
};

template <class Engine>
void bind_engine(Engine& e, sc_core::sc_signal_in_if<bool>& clk, InterpSignals& s) {
  e.clk_i(clk);
  e.rst_ni(s.rst_ni);
  e.feed_modulus_i(s.feed_modulus_i);
  e.frame_i(s.frame_i);
  e.frame_valid_i(s.frame_valid_i);
  e.tape_end_i(s.tape_end_i);
#define INTERP_OUTPUT(name, kind, width) e.name##_o(s.name##_o);
#include "interp_outputs.def"
#undef INTERP_OUTPUT
}

}  // namespace ncinterp::system
