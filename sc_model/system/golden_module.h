// The golden cycle model (ncinterp::GoldenInterp) as a SystemC module with exactly the
// ports of the verilated RTL (Vinterp_top: same names, same C++ port types), so the system
// model binds either engine to the same signals and traces them under the same names.
// Idea: one SC_METHOD on the rising clock edge: with rst_ni low it is GoldenInterp::reset(),
// otherwise one tick() with the inputs as they were before the edge; the outputs are
// written as registers (visible from the next delta on, like the RTL's).
#pragma once
#include <systemc>

#include "interp_top.h"

namespace ncinterp::system {

class GoldenInterpModule : public sc_core::sc_module {
 public:
  sc_core::sc_in<bool> clk_i{"clk_i"};
  sc_core::sc_in<bool> rst_ni{"rst_ni"};
  sc_core::sc_in<uint64_t> feed_modulus_i{"feed_modulus_i"};
  sc_core::sc_in<uint32_t> frame_i{"frame_i"};
  sc_core::sc_in<bool> frame_valid_i{"frame_valid_i"};
  sc_core::sc_in<bool> tape_end_i{"tape_end_i"};
#define INTERP_OUTPUT(name, kind, width) \
  sc_core::sc_out<Port##kind::Signal> name##_o{#name "_o"};
#include "interp_outputs.def"
#undef INTERP_OUTPUT

  // `cfg.feed_modulus` must equal the value driven on feed_modulus_i (checked at reset):
  // the C++ model takes it as a parameter, the RTL as a static input.
  GoldenInterpModule(sc_core::sc_module_name name, const InterpConfig& cfg);

 private:
  void edge();
  void write_outputs();

  GoldenInterp model_;
};

}  // namespace ncinterp::system
