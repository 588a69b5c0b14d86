// The RTL's assertions run in every verilated model and stop a run that breaks them: a copy
// of the RTL with a planted bug (interp_top loads the next block while the playing one
// still runs; tests/rtl/CMakeLists.txt) plays the bundled gear outline until the feed
// generator's assertion "load and run never coincide" fails, and the harness
// (VerilatedInterp) turns that into an exception instead of an abort. The same tape on the
// golden model plays to its end, so it is the bug that stops the run, not the tape.
#include <gtest/gtest.h>

#include <stdexcept>
#include <string>

#include "Vinterp_planted_bug.h"
#include "frame_source.h"
#include "interp_top.h"
#include "tape.h"
#include "verilated_interp.h"

namespace ncinterp {
namespace {

template <class Engine>
void play_to_end(Engine& engine, const std::vector<uint8_t>& frames) {
  FrameSource source(frames, 20);
  for (uint64_t cycle = 0; cycle < 50'000'000; ++cycle) {
    const bool ready = engine.outputs().frame_ready;
    engine.tick(source.inputs());
    source.clock(ready);
    if (engine.outputs().done || engine.outputs().error) return;
  }
}

TEST(PlantedBug, AnAssertionInsideTheRtlStopsTheRun) {
  const std::vector<uint8_t> frames = tape::load_frames(std::string(NCINTERP_EXAMPLES_DIR) + "/gear.nc");
  const InterpConfig cfg = interp_config(1e6);

  GoldenInterp golden(cfg);
  play_to_end(golden, frames);
  ASSERT_TRUE(golden.outputs().done);

  VerilatedInterp<Vinterp_planted_bug> rtl(cfg, cfg);
  testing::internal::CaptureStdout();
  try {
    play_to_end(rtl, frames);
    testing::internal::GetCapturedStdout();
    FAIL() << "the planted bug ran to the end without an assertion";
  } catch (const std::runtime_error& e) {
    const std::string printed = testing::internal::GetCapturedStdout();
    EXPECT_NE(std::string(e.what()).find("failed assertion"), std::string::npos) << e.what();
    EXPECT_NE(printed.find("a_load_not_running"), std::string::npos) << printed;
  }
}

}  // namespace
}  // namespace ncinterp
