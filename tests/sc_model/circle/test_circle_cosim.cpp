// Circle mode in lock step: the verilated RTL equals the golden model on every clock for the
// 50 mm circle of four quadrant blocks, for random programs of hundreds of quadrant arcs
// (radius 1 BLU to 2^16 - 1, both directions, every quadrant, full and partial) mixed with
// lines, and for bad arcs; every run also passes the program checks (exact ends, pulse
// counts, path bounds, block times).
#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <string>

#include "circle_program.h"
#include "interp_test_support.h"
#include "lockstep.h"

namespace ncinterp {
namespace {

using cosim::Options;
using cosim::Result;
using test::BlockClocks;
using test::OutputRecorder;

Options options_at(double clock_hz, Arch arch = Arch::kSerial) {
  Options o;
  o.config = interp_config(clock_hz);
  o.config.arch = arch;
  o.cycles_per_frame = 1;
  o.max_cycles = 100'000'000;
  return o;
}

Result run(const std::vector<uint8_t>& frames, const Options& o, OutputRecorder& rec,
           BlockClocks& clocks) {
  return cosim::run_lockstep(frames, o, [&](uint64_t c, const InterpOutputs& out) {
    rec.observe(c, out);
    if (c > 0) clocks.observe(out);
  });
}

void fifty_millimetre_circle(Arch arch) {
  const Options o = options_at(1e6, arch);
  tape::Program p;
  const int64_t r = 50000;
  const int64_t start[4][2] = {{r, 0}, {0, r}, {-r, 0}, {0, -r}};
  for (int q = 0; q < 4; ++q) {
    tape::Block b;
    b.n = static_cast<uint32_t>(q + 1);
    b.motion = tape::Motion::kArcCcw;
    b.i = -start[q][0];
    b.j = -start[q][1];
    b.dx = start[(q + 1) % 4][0] - start[q][0];
    b.dy = start[(q + 1) % 4][1] - start[q][1];
    b.feed = 300000;  // 0.2 s per quadrant
    p.blocks.push_back(b);
  }
  OutputRecorder rec;
  BlockClocks clocks;
  const Result res = run(test::program_frames(p), o, rec, clocks);
  ASSERT_FALSE(res.mismatch) << cosim::describe(*res.mismatch);
  ASSERT_EQ(res.end, Result::End::kDone);
  EXPECT_EQ(res.last.pos_x, 0);
  EXPECT_EQ(res.last.pos_y, 0);
  ASSERT_TRUE(test::check_program_run(p, rec, clocks, o.config));
  double worst = 0;
  for (const auto& pulse : rec.pulses)
    worst = std::max(worst, std::fabs(std::hypot(double(pulse.x + r), double(pulse.y)) - double(r)));
  EXPECT_LE(worst, kCircleDdaBound);
}

TEST(CircleCosim, FiftyMillimetreCircleOfFourQuadrantsSerial) {
  fifty_millimetre_circle(Arch::kSerial);
}
TEST(CircleCosim, FiftyMillimetreCircleOfFourQuadrantsParallel) {
  fifty_millimetre_circle(Arch::kParallel);
}

// Random programs in shards, so ctest can run them in parallel: 4 shards x 8 tapes x 12
// blocks, about 80 % arcs: some 300 arcs; every other tape in each arch.
class CircleCosimRandom : public ::testing::TestWithParam<int> {};

TEST_P(CircleCosimRandom, RtlEqualsGoldenOnArcProgramsAndThePathIsExact) {
  const int shard = GetParam();
  std::mt19937_64 rng(1000 + shard);
  for (int t = 0; t < 8; ++t) {
    // High feeds saturate: short runs.
    const Options o = options_at(1e3, t % 2 ? Arch::kParallel : Arch::kSerial);
    const tape::Program p = test::random_arc_program(rng, 12, 0.8, o.config.feed_modulus);
    OutputRecorder rec;
    BlockClocks clocks;
    const Result res = run(test::program_frames(p), o, rec, clocks);
    ASSERT_FALSE(res.mismatch) << "shard " << shard << " tape " << t << ": "
                               << cosim::describe(*res.mismatch);
    ASSERT_EQ(res.end, Result::End::kDone) << "shard " << shard << " tape " << t;
    ASSERT_EQ(res.stats.blocks, p.blocks.size());
    ASSERT_TRUE(test::check_program_run(p, rec, clocks, o.config))
        << "shard " << shard << " tape " << t;
  }
}

INSTANTIATE_TEST_SUITE_P(Shards, CircleCosimRandom, ::testing::Range(0, 4));

TEST(CircleCosim, BadArcsStopBothEnginesAlike) {
  const Options o = options_at(1e6);
  const std::vector<std::string> bad = {
      "G03 X-1.000 Y1.000 I0.000 J0.000",    // zero radius
      "G02 X-1.000 Y1.000 I-1.000 J0.000",   // three quadrants
      "G03 X-1.000 Y1.100 I-1.000 J0.000",   // end off the circle
      "G02 X65.535 Y-46.341 I-0.001 J-46.341",  // end outside the register
  };
  for (const std::string& words : bad) {
    const std::string text = "%\nG17 G21 G91 G93\nN1 G03 X-0.500 Y0.500 I-0.500 J0.000 F600.000\nN2 " +
                             words + " F600.000\nM02\n%\n";
    OutputRecorder rec;
    BlockClocks clocks;
    const Result res = run(test::frames_of(text), o, rec, clocks);
    ASSERT_FALSE(res.mismatch) << words << ": " << cosim::describe(*res.mismatch);
    ASSERT_EQ(res.end, Result::End::kTapeError) << words;
    EXPECT_EQ(res.last.error_block, 2u) << words;
    EXPECT_EQ(res.last.pos_x, -500) << words;
    EXPECT_EQ(res.last.pos_y, 500) << words;
  }
}

}  // namespace
}  // namespace ncinterp
