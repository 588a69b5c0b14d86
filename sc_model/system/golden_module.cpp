// The golden model as a SystemC module (see golden_module.h).
#include "golden_module.h"

#include <stdexcept>
#include <string>

namespace ncinterp::system {

GoldenInterpModule::GoldenInterpModule(sc_core::sc_module_name name, const InterpConfig& cfg)
    : sc_core::sc_module(name), model_(cfg) {
  SC_HAS_PROCESS(GoldenInterpModule);
  SC_METHOD(edge);
  sensitive << clk_i.pos();
  dont_initialize();
}

void GoldenInterpModule::edge() {
  if (!rst_ni.read()) {
    if (feed_modulus_i.read() != model_.config().feed_modulus)
      throw std::logic_error("golden model: feed_modulus_i " +
                             std::to_string(feed_modulus_i.read()) +
                             " differs from its configuration");
    model_.reset();
  } else {
    InterpInputs in;
    in.frame = static_cast<uint8_t>(frame_i.read());
    in.frame_valid = frame_valid_i.read();
    in.tape_end = tape_end_i.read();
    model_.tick(in);
  }
  write_outputs();
}

void GoldenInterpModule::write_outputs() {
  const InterpOutputs& o = model_.outputs();
  const unsigned pos_bits = model_.config().pos_width;
  const uint64_t pos_mask = pos_bits >= 64 ? ~0ull : (1ull << pos_bits) - 1;
  frame_ready_o.write(o.frame_ready);
  step_x_o.write(o.step_x);
  dir_x_o.write(o.dir_x);
  step_y_o.write(o.step_y);
  dir_y_o.write(o.dir_y);
  pos_x_o.write(static_cast<uint32_t>(static_cast<uint64_t>(o.pos_x) & pos_mask));
  pos_y_o.write(static_cast<uint32_t>(static_cast<uint64_t>(o.pos_y) & pos_mask));
  block_n_o.write(o.block_n);
  busy_o.write(o.busy);
  done_o.write(o.done);
  error_o.write(o.error);
  error_code_o.write(o.error_code);
  error_block_o.write(o.error_block);
  error_offset_o.write(o.error_offset);
  feed_saturated_o.write(o.feed_saturated);
}

}  // namespace ncinterp::system
