// SystemC tape reader: delivers a tape's frames to the interpolator over valid/ready at a
// reader rate (characters per second).
// Idea: the timing is ncinterp::FrameSource's (sc_model/golden/frame_source.h), the very
// same object the lock-step cosim uses, so a SystemC run and a cosim run feed the engine
// identical inputs clock by clock. At each rising edge (out of reset) the reader takes the
// engine's frame_ready from before the edge, advances, and drives the next clock's inputs.
#pragma once
#include <systemc>

#include "frame_source.h"

namespace ncinterp::system {

class TapeReaderModule : public sc_core::sc_module {
 public:
  sc_core::sc_in<bool> clk_i{"clk_i"};
  sc_core::sc_in<bool> rst_ni{"rst_ni"};
  sc_core::sc_in<bool> frame_ready_i{"frame_ready_i"};
  sc_core::sc_out<uint32_t> frame_o{"frame_o"};  // 8-bit frame (the engine's port type)
  sc_core::sc_out<bool> frame_valid_o{"frame_valid_o"};
  sc_core::sc_out<bool> tape_end_o{"tape_end_o"};

  TapeReaderModule(sc_core::sc_module_name name, FrameSource source);
  const FrameSource& source() const { return source_; }

 private:
  void start_of_simulation() override { drive(); }
  void edge();
  void drive();

  FrameSource source_;
};

}  // namespace ncinterp::system
