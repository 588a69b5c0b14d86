// The three verilated flavours of interp_top link into one executable with one Verilator
// runtime (rtl/CMakeLists.txt) and behave alike: after reset every output is idle and
// frame_ready is high; a clocked run of a one-block tape reaches done in all of them.
#include <gtest/gtest.h>

#include <string>
#include <systemc>
#include <vector>

#include "Vinterp_top.h"
#include "Vinterp_top_sc.h"
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
  // The default context (Verilated::threadContextp()), as the SystemC model below uses.
  Vinterp_top fast;
  Vinterp_top_trace traced;
  EXPECT_EQ(run_cpp(fast), 3);
  EXPECT_EQ(run_cpp(traced), 3);
  EXPECT_EQ(fast.pos_y_o, traced.pos_y_o);
}

TEST(VerilatedModels, SystemCFlavourElaboratesAndResets) {
  sc_core::sc_clock clk("clk", 1, sc_core::SC_US);
  sc_core::sc_signal<bool> rst_n("rst_n"), valid("valid"), tape_end("tape_end");
  sc_core::sc_signal<uint64_t> modulus("modulus");
  sc_core::sc_signal<uint32_t> frame("frame");
  sc_core::sc_signal<bool> ready, step_x, dir_x, step_y, dir_y, busy, done, error, sat;
  sc_core::sc_signal<uint32_t> pos_x, pos_y, block_n, code, eblock, eoffset;
  Vinterp_top_sc dut("dut");
  dut.clk_i(clk);
  dut.rst_ni(rst_n);
  dut.feed_modulus_i(modulus);
  dut.frame_i(frame);
  dut.frame_valid_i(valid);
  dut.tape_end_i(tape_end);
  dut.frame_ready_o(ready);
  dut.step_x_o(step_x);
  dut.dir_x_o(dir_x);
  dut.step_y_o(step_y);
  dut.dir_y_o(dir_y);
  dut.pos_x_o(pos_x);
  dut.pos_y_o(pos_y);
  dut.block_n_o(block_n);
  dut.busy_o(busy);
  dut.done_o(done);
  dut.error_o(error);
  dut.error_code_o(code);
  dut.error_block_o(eblock);
  dut.error_offset_o(eoffset);
  dut.feed_saturated_o(sat);
  modulus = kModulus;
  rst_n = false;
  sc_core::sc_start(3, sc_core::SC_US);
  EXPECT_TRUE(ready.read());
  EXPECT_FALSE(busy.read() || done.read() || error.read());
  rst_n = true;
  tape_end = true;  // an empty tape: truncated at offset 0
  sc_core::sc_start(5, sc_core::SC_US);
  EXPECT_TRUE(error.read());
  EXPECT_EQ(code.read(), 7u);
  EXPECT_EQ(eoffset.read(), 0u);
}

}  // namespace

// libsystemc's own main() is not used (GoogleTest's is), but the library references sc_main.
int sc_main(int, char**) { return 0; }
