// SystemC tape reader (see tape_reader_module.h).
#include "tape_reader_module.h"

namespace ncinterp::system {

TapeReaderModule::TapeReaderModule(sc_core::sc_module_name name, FrameSource source)
    : sc_core::sc_module(name), source_(std::move(source)) {
  SC_HAS_PROCESS(TapeReaderModule);
  SC_METHOD(edge);
  sensitive << clk_i.pos();
  dont_initialize();
}

void TapeReaderModule::edge() {
  if (!rst_ni.read()) return;  // held at the first frame during reset
  source_.clock(frame_ready_i.read());
  drive();
}

void TapeReaderModule::drive() {
  const InterpInputs in = source_.inputs();
  frame_o.write(in.frame);
  frame_valid_o.write(in.frame_valid);
  tape_end_o.write(in.tape_end);
}

}  // namespace ncinterp::system
