// Gate-level lock step: interp_top as synth_ice40 maps it (gate_netlist.sh: the mapped
// netlist with the iCE40 cells' simulation models, verilated as NCINTERP_GATE_MODEL) against
// the golden model, every output after every clock, on a tape of lines and quadrant arcs of
// both directions and on a tape whose arc ends off its circle (error 11 at the block's LF).
// What it guards: that synthesis builds the machine the RTL simulation shows (docs/
// verification.md); a 'x on a path that matters simulates right and synthesises wrong.
// Built twice (tests/rtl/CMakeLists.txt): NCINTERP_GATE_MODEL names the verilated netlist,
// and with NCINTERP_RTL_BIT_SERIAL it is interp_top with BitSerial (the boards'), played
// against the golden model configured alike.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#define NCINTERP_STRINGIFY(x) #x
#define NCINTERP_HEADER(model) NCINTERP_STRINGIFY(model.h)
#include NCINTERP_HEADER(NCINTERP_GATE_MODEL)
#include "frame_source.h"
#include "interp_top.h"
#include "tape.h"
#include "verilated_interp.h"

namespace ncinterp {
namespace {

// The first output port (interp_outputs.def) whose values differ.
std::string first_difference(const InterpOutputs& g, const InterpOutputs& r) {
#define INTERP_OUTPUT(name, kind, width) \
  if (!(g.name == r.name)) return #name "_o: golden " + std::to_string(static_cast<int64_t>(g.name)) + \
                                   ", gate " + std::to_string(static_cast<int64_t>(r.name));
#include "interp_outputs.def"
#undef INTERP_OUTPUT
  return "none";
}

// Plays `text` on the gate-level netlist and the golden model, one frame per clock;
// returns the golden outputs at the end, failing at the first clock where any differs.
InterpOutputs play_in_lock_step(const std::string& text) {
  InterpConfig cfg = interp_config(1e6);
  cfg.arch = NCINTERP_RTL_BIT_SERIAL ? Arch::kSerial : Arch::kParallel;
  GoldenInterp golden(cfg);
  VerilatedInterp<NCINTERP_GATE_MODEL> gate(cfg, cfg);
  golden.reset();
  FrameSource source(tape::add_parity(text), 1);
  EXPECT_TRUE(gate.same_as(golden.outputs())) << "after reset";
  for (uint64_t cycle = 1; cycle < 200000; ++cycle) {
    const bool ready = golden.outputs().frame_ready;
    const InterpInputs in = source.inputs();
    golden.tick(in);
    gate.tick(in);
    source.clock(ready);
    if (!gate.same_as(golden.outputs())) {
      ADD_FAILURE() << "cycle " << cycle << ": gate level differs from the golden model, "
                    << first_difference(golden.outputs(), gate.outputs());
      return golden.outputs();
    }
    if (golden.outputs().done || golden.outputs().error) return golden.outputs();
  }
  ADD_FAILURE() << "the tape did not end";
  return golden.outputs();
}

// 1000 clocks per block at 1 MHz (F = 60000 per minute).
TEST(GateLevel, LinesAndArcsPlayAsTheGoldenModel) {
  const InterpOutputs end = play_in_lock_step(
      "%\n"
      "N1 G01 X0.010 Y0.005 F60000.000\n"
      "N2 G03 X-0.020 Y0.020 I-0.020 J0.000\n"    // ccw quadrant, radius 20 BLU
      "N3 G02 X0.030 Y-0.030 I0.000 J-0.030\n"    // cw quadrant, radius 30 BLU
      "N4 G01 X-0.020 Y0.005\n"
      "M02\n%\n");
  EXPECT_TRUE(end.done);
  EXPECT_EQ(end.pos_x, 0);
  EXPECT_EQ(end.pos_y, 0);
}

TEST(GateLevel, ArcOffItsCircleStopsAsTheGoldenModel) {
  const InterpOutputs end = play_in_lock_step(
      "%\n"
      "N1 G01 X0.004 F60000.000\n"
      "N2 G03 X-0.020 Y0.025 I-0.020 J0.000\n"    // ends 5 BLU off the circle
      "M02\n%\n");
  EXPECT_TRUE(end.error);
  EXPECT_EQ(end.error_code, static_cast<uint8_t>(TapeError::kArcEndpointOffCircle));
  EXPECT_EQ(end.error_block, 2u);
}

}  // namespace
}  // namespace ncinterp
