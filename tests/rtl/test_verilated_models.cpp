// The two verilated flavours of interp_top link into one executable with one Verilator
// runtime (rtl/CMakeLists.txt) and behave alike: after reset every output is idle and
// frame_ready is high; a clocked run of a one-block tape reaches done in all of them.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "Vinterp_top.h"
#include "Vinterp_top_trace.h"
#include "frame_source.h"
#include "verilated.h"

namespace {

std::vector<uint8_t> frames_of(const std::string& text) {
  std::vector<uint8_t> frames;
  for (char c : text) {
    const uint8_t ch = static_cast<uint8_t>(c) & 0x7f;
    frames.push_back(static_cast<uint8_t>(ch | (__builtin_parity(ch) ? 0x80 : 0)));
  }
  return frames;
}

const std::string kTape = "%\nN1 G01 X0.003 Y-0.002 F100000.000\nM02\n%\n";
constexpr uint64_t kModulus = 60ull * 1000 * 1000;  // 1 kHz clock

// Runs a C++ flavour to done (or 10000 clocks); returns the final x position.
template <typename Model>
int run_cpp(Model& m) {
  ncinterp::FrameSource src(frames_of(kTape), 1);
  m.feed_modulus_i = kModulus;
  m.rst_ni = 0;
  m.clk_i = 0;
  m.eval();
  m.clk_i = 1;
  m.eval();
  m.rst_ni = 1;
  EXPECT_TRUE(m.frame_ready_o);
  EXPECT_FALSE(m.busy_o || m.done_o || m.error_o || m.step_x_o || m.step_y_o);
  for (int i = 0; i < 10000 && !m.done_o && !m.error_o; ++i) {
    const bool ready = m.frame_ready_o;
    const auto in = src.inputs();
    m.frame_i = in.frame;
    m.frame_valid_i = in.frame_valid;
    m.tape_end_i = in.tape_end;
    m.clk_i = 0;
    m.eval();
    m.clk_i = 1;
    m.eval();
    src.clock(ready);
  }
  EXPECT_TRUE(m.done_o);
  return static_cast<int>(m.pos_x_o);
}

TEST(VerilatedModels, CppAndTraceFlavoursRunTheSameTape) {
  // The default context (Verilated::threadContextp()).
  Vinterp_top fast;
  Vinterp_top_trace traced;
  EXPECT_EQ(run_cpp(fast), 3);
  EXPECT_EQ(run_cpp(traced), 3);
  EXPECT_EQ(fast.pos_y_o, traced.pos_y_o);
}

}  // namespace

