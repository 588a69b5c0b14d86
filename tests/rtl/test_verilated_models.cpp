// The verilated models of interp_top, both archs with and without tracing, link into one
// executable with one Verilator runtime (rtl/CMakeLists.txt) and behave alike: after reset
// every output is idle and frame_ready is high; a clocked run of a one-block tape reaches
// done in all of them at the same position, the serial arch in more clocks.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "frame_source.h"
#include "rtl_models.h"
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

struct End {
  int x = 0, y = 0, clocks = 0;
};

// Runs a C++ flavour to done (or 10000 clocks).
template <typename Model>
End run_cpp(Model& m) {
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
  int clocks = 0;
  for (; clocks < 10000 && !m.done_o && !m.error_o; ++clocks) {
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
  return End{static_cast<int>(m.pos_x_o), static_cast<int>(m.pos_y_o), clocks};
}

TEST(VerilatedModels, EveryArchAndFlavourRunsTheSameTape) {
  // The default context (Verilated::threadContextp()).
  Vinterp_serial serial;
  Vinterp_serial_trace serial_traced;
  Vinterp_parallel parallel;
  Vinterp_parallel_trace parallel_traced;
  const End s = run_cpp(serial), st = run_cpp(serial_traced);
  const End p = run_cpp(parallel), pt = run_cpp(parallel_traced);
  for (const End& e : {s, st, p, pt}) {
    EXPECT_EQ(e.x, 3);
    EXPECT_EQ(e.y, -2);
  }
  EXPECT_EQ(s.clocks, st.clocks);
  EXPECT_EQ(p.clocks, pt.clocks);
  EXPECT_GT(s.clocks, p.clocks);
}

}  // namespace

