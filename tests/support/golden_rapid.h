// Whether this build's golden model plays G00 (rapid traverse) blocks: tests of tapes with
// traverses play them only then, and say so when they skip (GTEST_SKIP).
// Idea: ask the model itself with the smallest tape that has a G00 block, so the tests turn
// on by themselves once the interpolator accepts G00 (until then it stops with code 6,
// unsupported G code).
#pragma once
#include <cstdint>
#include <string>
#include <vector>

#include "frame_source.h"
#include "interp_top.h"

namespace ncinterp::test {

inline bool golden_plays_rapid() {
  static const bool plays = [] {
    const std::string text = "%\nG17 G21 G91 G93\nN1 G00 X0.010 Y0.000\nN2 G01 X0.010 Y0.000 F100.000\nM02\n%\n";
    std::vector<uint8_t> frames;
    for (char c : text) {
      uint8_t f = static_cast<uint8_t>(c);
      if (__builtin_popcount(f) & 1) f |= 0x80;
      frames.push_back(f);
    }
    GoldenInterp dut{InterpConfig{}};
    dut.reset();
    FrameSource source(frames, 1);
    for (uint64_t c = 0; c < 10'000'000 && !dut.outputs().done && !dut.outputs().error; ++c) {
      const bool ready = dut.outputs().frame_ready;
      dut.tick(source.inputs());
      source.clock(ready);
    }
    return dut.outputs().done && dut.outputs().pos_x == 20;
  }();
  return plays;
}

}  // namespace ncinterp::test
