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
  const InterpConfig& cfg = model_.config();
#define INTERP_OUTPUT(name, kind, width) name##_o.write(Port##kind::to_signal(o.name, width));
#include "interp_outputs.def"
#undef INTERP_OUTPUT
}

}  // namespace ncinterp::system
