// Writer -> reader round trip on random programs, exact text of a known program, and
// ISO 840 parity on every frame.
#include <gtest/gtest.h>

#include <random>
#include <string>

using namespace std::string_literals;

#include "quadrant_arc.h"
#include "tape.h"

namespace ncinterp::tape {
namespace {

bool same_blocks(const Program& a, const Program& b) {
  if (a.blocks.size() != b.blocks.size() || a.end_m30 != b.end_m30) return false;
  for (size_t k = 0; k < a.blocks.size(); ++k) {
    const Block &x = a.blocks[k], &y = b.blocks[k];
    if (x.n != y.n || x.motion != y.motion || x.dx != y.dx || x.dy != y.dy || x.i != y.i ||
        x.j != y.j || x.feed != y.feed)
      return false;
  }
  return true;
}

TEST(TapeWriter, KnownProgramText) {
  Program p;
  p.blocks.push_back({1, Motion::kLine, 12345, -5, 0, 0, 60000});
  p.blocks.push_back({2, Motion::kArcCcw, -1000, 1000, -1000, 0, 1500});
  p.blocks.push_back({3, Motion::kLine, 0, 0, 0, 0, 1});
  EXPECT_EQ(format_program(p, Format{}),
            "%\n"
            "G17 G21 G91 G93\n"
            "N1 G01 X12.345 Y-0.005 F60.000\n"
            "N2 G03 X-1.000 Y1.000 I-1.000 J0.000 F1.500\n"
            "N3 G01 X0.000 Y0.000 F0.001\n"
            "M02\n"
            "%\n");
  p.end_m30 = true;
  Format f;
  f.frac_digits = 0;
  f.feed_frac_digits = 1;
  p.blocks.resize(1);
  EXPECT_EQ(format_program(p, f), "%\nG17 G21 G91 G93\nN1 G01 X12345. Y-5. F6000.0\nM30\n%\n");
}

TEST(TapeWriter, TraversesAreG00WithoutFAndReadBackWithFeedZero) {
  Program p;
  p.blocks.push_back({1, Motion::kRapid, 20000, -3000, 0, 0, 0});
  p.blocks.push_back({2, Motion::kLine, 5, 0, 0, 0, 1000});
  const std::string text = format_program(p, Format{});
  EXPECT_EQ(text,
            "%\nG17 G21 G91 G93\nN1 G00 X20.000 Y-3.000\nN2 G01 X0.005 Y0.000 F1.000\nM02\n%\n");
  const Program back = parse_frames(add_parity(text), Format{});
  ASSERT_EQ(back.blocks.size(), 2u);
  EXPECT_EQ(back.blocks[0].motion, Motion::kRapid);
  EXPECT_EQ(back.blocks[0].feed, 0u);
  EXPECT_EQ(back.blocks[0].dx, 20000);
  // An F on a G00 block is modal for what follows; the G00 block itself keeps feed 0.
  const Program modal = parse_frames(
      add_parity("%\nN1 G00 X1.000 Y0.000 F5.000\nN2 G01 X1.000\nM02\n%\n"), Format{});
  ASSERT_EQ(modal.blocks.size(), 2u);
  EXPECT_EQ(modal.blocks[0].feed, 0u);
  EXPECT_EQ(modal.blocks[1].feed, 5000u);
  // The first G01 after a G00 still needs an F: the rapid gives it none.
  EXPECT_THROW(parse_frames(add_parity("%\nN1 G00 X1.000 Y0.000\nN2 G01 X1.000\nM02\n%\n"), Format{}),
               TapeFormatError);
  // The writer refuses what it could not read back: an F or I/J on a G00 block.
  p.blocks[0].feed = 7;
  EXPECT_THROW(format_program(p, Format{}), std::invalid_argument);
  p.blocks[0] = {1, Motion::kRapid, 1, 1, 5, 0, 0};
  EXPECT_THROW(format_program(p, Format{}), std::invalid_argument);
}

TEST(TapeWriter, RefusesValuesTheDecoderWouldReject) {
  Format f;  // inc_width 16: |d| <= 65535
  Program p;
  p.blocks.push_back({1, Motion::kLine, 65536, 0, 0, 0, 1000});
  EXPECT_THROW(format_program(p, f), std::invalid_argument);
  p.blocks[0].dx = -65535;
  EXPECT_NO_THROW(format_program(p, f));
  p.blocks[0].feed = 0;
  EXPECT_THROW(format_program(p, f), std::invalid_argument);
  p.blocks[0] = {1, Motion::kLine, 1, 1, 5, 0, 1000};  // I on a line
  EXPECT_THROW(format_program(p, f), std::invalid_argument);
  p.blocks[0] = {1u << 20, Motion::kLine, 1, 1, 0, 0, 1000};  // N beyond SeqWidth 20
  EXPECT_THROW(format_program(p, f), std::invalid_argument);
  p.blocks[0] = {1, Motion::kArcCcw, 1000, 1000, 1000, 0, 1000};  // leaves its quadrant
  EXPECT_THROW(format_program(p, f), std::invalid_argument);
  p.blocks[0] = {1, Motion::kArcCcw, -1000, 1000, -1000, 0, 1000};  // a good quadrant
  EXPECT_NO_THROW(format_program(p, f));
}

TEST(TapeParity, EveryFrameHasEvenParity) {
  for (int c = 0; c < 128; ++c) {
    const std::string s(1, static_cast<char>(c));
    const uint8_t frame = add_parity(s)[0];
    EXPECT_EQ(frame & 0x7f, c);
    EXPECT_EQ(__builtin_popcount(frame) % 2, 0) << "char " << c;
    EXPECT_TRUE(has_even_parity(frame));
    EXPECT_FALSE(has_even_parity(frame ^ 0x80));
  }
  EXPECT_EQ(add_parity("%")[0], 0xA5);  // 0x25 has three ones
  EXPECT_EQ(add_parity("\n")[0], 0x0A);
  EXPECT_EQ(add_parity("X")[0], 0xD8);  // 0x58 has three ones
}

Program random_program(std::mt19937_64& rng, const Format& f) {
  const int64_t inc_max = (int64_t{1} << f.inc_width) - 1;
  std::uniform_int_distribution<int64_t> inc(-inc_max, inc_max);
  std::uniform_int_distribution<uint64_t> feed(1, (uint64_t{1} << f.feed_width) - 1);
  std::uniform_int_distribution<int> count(0, 30), kind(0, 6);
  Program p;
  p.end_m30 = rng() & 1;
  uint32_t n = static_cast<uint32_t>(rng() % 100);
  const int blocks = count(rng);
  for (int k = 0; k < blocks; ++k) {
    Block b;
    n += static_cast<uint32_t>(rng() % 20);  // repeated N is legal too
    b.n = n % (1u << f.seq_width);
    const int what = kind(rng);
    b.dx = what == 1 ? 0 : inc(rng);  // axis-parallel and zero moves appear too
    b.dy = what == 2 ? 0 : inc(rng);
    if (what == 3) b.dx = b.dy = 0;
    b.feed = feed(rng);
    if (what == 6) {  // a traverse: no F
      b.motion = Motion::kRapid;
      b.feed = 0;
    }
    if (what == 4 || what == 5)  // arcs must be good arcs: the reader checks them like the decoder
      b = quadrant_arc(b.n, 1 + std::llabs(inc(rng)) % inc_max, static_cast<int>(rng() % 4),
                       what == 5, b.feed);
    p.blocks.push_back(b);
  }
  return p;
}

TEST(TapeRoundTrip, RandomProgramsReadBackExactly) {
  std::mt19937_64 rng(20240611);
  for (int trial = 0; trial < 500; ++trial) {
    Format f;
    f.frac_digits = static_cast<unsigned>(rng() % 5);
    f.feed_frac_digits = static_cast<unsigned>(rng() % 4);
    f.inc_width = 4 + static_cast<unsigned>(rng() % 27);
    f.feed_width = 8 + static_cast<unsigned>(rng() % 25);
    f.seq_width = 8 + static_cast<unsigned>(rng() % 13);
    const Program p = random_program(rng, f);
    const std::string text = format_program(p, f);
    const std::vector<uint8_t> frames = add_parity(text);
    for (const uint8_t frame : frames) ASSERT_TRUE(has_even_parity(frame));
    Program back;
    ASSERT_NO_THROW(back = parse_frames(frames, f)) << text;
    ASSERT_TRUE(same_blocks(p, back)) << text;
  }
}

TEST(TapeReader, AcceptsWhatTheDecoderAccepts) {
  // Spaces/CR inside numbers, leading zeros, comments, leader before '%', modal G and F,
  // a block without N (it carries the previous N), M02 in a motion block, NULs after the end.
  const std::string text =
      "TITLE 1\n%\r\n(setup)\nG17G21G91G93\nN007 G1 X1 2.000 Y+0.500 F2.000\n"
      "X-0.001\nN9 Y3.000 M30\n%\n\0\0"s;
  const Program p = parse_frames(add_parity(text), Format{});
  ASSERT_EQ(p.blocks.size(), 3u);
  EXPECT_EQ(p.blocks[0].n, 7u);
  EXPECT_EQ(p.blocks[0].dx, 12000);
  EXPECT_EQ(p.blocks[0].dy, 500);
  EXPECT_EQ(p.blocks[1].n, 7u);
  EXPECT_EQ(p.blocks[1].dx, -1);
  EXPECT_EQ(p.blocks[1].dy, 0);
  EXPECT_EQ(p.blocks[1].feed, 2000u);
  EXPECT_EQ(p.blocks[2].n, 9u);
  EXPECT_EQ(p.blocks[2].dy, 3000);
  EXPECT_TRUE(p.end_m30);
}

TEST(TapeReader, EmptyProgramIsValid) {
  const Program p = parse_frames(add_parity("%\nG17 G21 G91 G93\nM02\n%\n"), Format{});
  EXPECT_TRUE(p.blocks.empty());
  EXPECT_FALSE(p.end_m30);
}

}  // namespace
}  // namespace ncinterp::tape
