// The signals around the interpolator in the system model, named after its ports, and the
// one function that binds an engine to them.
// Idea: the golden SystemC module and the verilated RTL (Vinterp_top) have the same port
// names and C++ port types, so one template binds either; the reader and the monitor only
// ever see these signals.
#pragma once
#include <systemc>

namespace ncinterp::system {

struct InterpSignals {
  sc_core::sc_signal<bool> rst_ni{"rst_ni"};
  sc_core::sc_signal<uint64_t> feed_modulus_i{"feed_modulus_i"};
  sc_core::sc_signal<uint32_t> frame_i{"frame_i"};
  sc_core::sc_signal<bool> frame_valid_i{"frame_valid_i"};
  sc_core::sc_signal<bool> tape_end_i{"tape_end_i"};
  sc_core::sc_signal<bool> frame_ready_o{"frame_ready_o"};
  sc_core::sc_signal<bool> step_x_o{"step_x_o"};
  sc_core::sc_signal<bool> dir_x_o{"dir_x_o"};
  sc_core::sc_signal<bool> step_y_o{"step_y_o"};
  sc_core::sc_signal<bool> dir_y_o{"dir_y_o"};
  sc_core::sc_signal<uint32_t> pos_x_o{"pos_x_o"};
  sc_core::sc_signal<uint32_t> pos_y_o{"pos_y_o"};
  sc_core::sc_signal<uint32_t> block_n_o{"block_n_o"};
  sc_core::sc_signal<bool> busy_o{"busy_o"};
  sc_core::sc_signal<bool> done_o{"done_o"};
  sc_core::sc_signal<bool> error_o{"error_o"};
  sc_core::sc_signal<uint32_t> error_code_o{"error_code_o"};
  sc_core::sc_signal<uint32_t> error_block_o{"error_block_o"};
  sc_core::sc_signal<uint32_t> error_offset_o{"error_offset_o"};
  sc_core::sc_signal<bool> feed_saturated_o{"feed_saturated_o"};
};

template <class Engine>
void bind_engine(Engine& e, sc_core::sc_signal_in_if<bool>& clk, InterpSignals& s) {
  e.clk_i(clk);
  e.rst_ni(s.rst_ni);
  e.feed_modulus_i(s.feed_modulus_i);
  e.frame_i(s.frame_i);
  e.frame_valid_i(s.frame_valid_i);
  e.tape_end_i(s.tape_end_i);
  e.frame_ready_o(s.frame_ready_o);
  e.step_x_o(s.step_x_o);
  e.dir_x_o(s.dir_x_o);
  e.step_y_o(s.step_y_o);
  e.dir_y_o(s.dir_y_o);
  e.pos_x_o(s.pos_x_o);
  e.pos_y_o(s.pos_y_o);
  e.block_n_o(s.block_n_o);
  e.busy_o(s.busy_o);
  e.done_o(s.done_o);
  e.error_o(s.error_o);
  e.error_code_o(s.error_code_o);
  e.error_block_o(s.error_block_o);
  e.error_offset_o(s.error_offset_o);
  e.feed_saturated_o(s.feed_saturated_o);
}

}  // namespace ncinterp::system
