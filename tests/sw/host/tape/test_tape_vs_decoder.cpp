// The software reader and the interpolator's decoder (golden model) must agree on every
// tape: thousands of randomly damaged tapes (bit flips, inserted, deleted and replaced
// characters, cut tapes) are read by parse_frames_partial and played by GoldenInterp.
// Agreement means: the same verdict; on an error the same code, block N and frame offset;
// and the machine's final position is the sum of the blocks the reader accepted (so no
// pulse comes from the bad block). The tapes mix lines and quadrant arcs, so damage also
// makes arcs that leave their quadrant, lose their radius or miss their circle, and G00
// (traverse) blocks are in the mix.
#include <gtest/gtest.h>

#include <random>

#include "frame_source.h"
#include "interp_top.h"
#include "quadrant_arc.h"
#include "tape.h"

namespace ncinterp::tape {
namespace {

std::string random_good_tape(std::mt19937_64& rng) {
  Program p;
  p.end_m30 = rng() & 1;
  const int blocks = static_cast<int>(rng() % 12);
  std::uniform_int_distribution<int64_t> inc(-999, 999), radius(1, 999);
  for (int k = 0; k < blocks; ++k) {
    const uint32_t n = static_cast<uint32_t>(k + 1);
    const uint64_t feed = 1 + rng() % 5000;
    if (rng() % 3 == 0)
      p.blocks.push_back(quadrant_arc(n, radius(rng), static_cast<int>(rng() % 4), rng() & 1, feed));
    else if (rng() % 5 == 0)
      p.blocks.push_back({n, Motion::kRapid, inc(rng), inc(rng), 0, 0, 0});
    else
      p.blocks.push_back({n, Motion::kLine, inc(rng), inc(rng), 0, 0, feed});
  }
  std::string text = format_program(p, Format{});
  if (rng() % 3 == 0) text.insert(2, "(part 7, rev B)\n");
  if (rng() % 3 == 0) text.insert(0, std::string(rng() % 5, '\0'));  // leader
  return text;
}

void damage(std::vector<uint8_t>& frames, std::mt19937_64& rng) {
  static const std::string alphabet = "NGMXYIJF0123456789+-. \r\n()%Qx\t\x7f";
  const auto any_char = [&] {
    return add_parity(std::string(1, alphabet[rng() % alphabet.size()]))[0];
  };
  const int ops = 1 + static_cast<int>(rng() % 3);
  for (int k = 0; k < ops && !frames.empty(); ++k) {
    const size_t at = rng() % frames.size();
    switch (rng() % 6) {
      case 0: frames[at] ^= static_cast<uint8_t>(1u << (rng() % 8)); break;
      case 1: frames[at] = any_char(); break;
      case 2: frames.erase(frames.begin() + static_cast<long>(at)); break;
      case 3: frames.insert(frames.begin() + static_cast<long>(at), any_char()); break;
      case 4: frames.resize(at); break;
      default: break;  // keep: some tapes stay good
    }
  }
}

struct MachineResult {
  InterpOutputs out;
  bool finished = false;
};

MachineResult play(const std::vector<uint8_t>& frames) {
  InterpConfig cfg;
  cfg.feed_modulus = 4096;  // short blocks: ceil(4096/F) clocks, or 2^k + 1 when saturated
  GoldenInterp dut(cfg);
  dut.reset();
  FrameSource source(frames, 1);
  while (!dut.outputs().done && !dut.outputs().error && dut.cycle() < 5'000'000) {
    const bool ready = dut.outputs().frame_ready;
    InterpInputs in = source.inputs();
    in.start = dut.outputs().paused;  // a damaged M02 may read M00: cycle start at once
    dut.tick(in);
    source.clock(ready);
  }
  return {dut.outputs(), dut.outputs().done || dut.outputs().error};
}

TEST(TapeReaderVsDecoder, DamagedTapesGetTheSameVerdict) {
  std::mt19937_64 rng(77);
  Format format;
  int errors = 0, good = 0, arc_errors = 0;
  for (int trial = 0; trial < 3000; ++trial) {
    const std::string text = random_good_tape(rng);
    std::vector<uint8_t> frames = add_parity(text);
    damage(frames, rng);
    const ParseResult r = parse_frames_partial(frames, format);
    const MachineResult m = play(frames);
    ASSERT_TRUE(m.finished) << "trial " << trial << ": the machine neither finished nor stopped";
    int64_t x = 0, y = 0;
    for (const Block& b : r.program.blocks) {
      x += b.dx;
      y += b.dy;
    }
    SCOPED_TRACE("trial " + std::to_string(trial));
    ASSERT_EQ(m.out.error, r.error.has_value())
        << (r.error ? describe(*r.error) : std::string("reader: ok"))
        << "; decoder code " << int(m.out.error_code);
    if (r.error) {
      ++errors;
      EXPECT_EQ(m.out.error_code, r.error->code) << describe(*r.error);
      EXPECT_EQ(m.out.error_block, r.error->block) << describe(*r.error);
      EXPECT_EQ(m.out.error_offset, r.error->offset) << describe(*r.error);
      arc_errors += r.error->code >= 10 && r.error->code <= 12;
    } else {
      ++good;
      EXPECT_TRUE(m.out.done);
    }
    EXPECT_EQ(m.out.pos_x, x);
    EXPECT_EQ(m.out.pos_y, y);
    if (::testing::Test::HasFailure()) break;
  }
  // The generator must exercise both outcomes.
  EXPECT_GT(errors, 1000);
  EXPECT_GT(good, 100);
  EXPECT_GT(arc_errors, 20);
}

}  // namespace
}  // namespace ncinterp::tape
