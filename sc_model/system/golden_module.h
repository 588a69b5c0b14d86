// The golden cycle model (ncinterp::GoldenInterp) as a SystemC module with exactly the
// ports of the verilated RTL (Vinterp_top: same names, same C++ port types), so the system
// model binds either engine to the same signals and traces them under the same names.
// Idea: one SC_METHOD on the rising clock edge: with rst_ni low it is GoldenInterp::reset(),
// otherwise one tick() with the inputs as they were before the edge; the outputs are
// written as registers (visible from the next delta on, like the RTL's).
#pragma once
#include <systemc>

#include "golden_interp.h"

namespace ncinterp::system {

class GoldenInterpModule : public sc_core::sc_module {
 public:
  sc_core::sc_in<bool> clk_i{"clk_i"};
  sc_core::sc_in<bool> rst_ni{"rst_ni"};
  sc_core::sc_in<uint64_t> feed_modulus_i{"feed_modulus_i"};
  sc_core::sc_in<uint32_t> frame_i{"frame_i"};
  sc_core::sc_in<bool> frame_valid_i{"frame_valid_i"};
  sc_core::sc_in<bool> tape_end_i{"tape_end_i"};
  sc_core::sc_out<bool> frame_ready_o{"frame_ready_o"};
  sc_core::sc_out<bool> step_x_o{"step_x_o"};
  sc_core::sc_out<bool> dir_x_o{"dir_x_o"};
  sc_core::sc_out<bool> step_y_o{"step_y_o"};
  sc_core::sc_out<bool> dir_y_o{"dir_y_o"};
  sc_core::sc_out<uint32_t> pos_x_o{"pos_x_o"};
  sc_core::sc_out<uint32_t> pos_y_o{"pos_y_o"};
  sc_core::sc_out<uint32_t> block_n_o{"block_n_o"};
  sc_core::sc_out<bool> busy_o{"busy_o"};
  sc_core::sc_out<bool> done_o{"done_o"};
  sc_core::sc_out<bool> error_o{"error_o"};
  sc_core::sc_out<uint32_t> error_code_o{"error_code_o"};
  sc_core::sc_out<uint32_t> error_block_o{"error_block_o"};
  sc_core::sc_out<uint32_t> error_offset_o{"error_offset_o"};
  sc_core::sc_out<bool> feed_saturated_o{"feed_saturated_o"};

  // `cfg.feed_modulus` must equal the value driven on feed_modulus_i (checked at reset):
  // the C++ model takes it as a parameter, the RTL as a static input.
  GoldenInterpModule(sc_core::sc_module_name name, const InterpConfig& cfg);

 private:
  void edge();
  void write_outputs();

  GoldenInterp model_;
};

}  // namespace ncinterp::system
