// Module-level lock step of the bit-serial DDA (rtl/dda_serial.sv) against its golden twin
// SerialDda, every clock: every good arc and every line of a 4-bit register, and random
// ones at W = 6 (passes longer than W) and W = 16, under random iteration strobes. The twin
// computes each iteration with CircleDda, the parallel DDA's integers, so this checks the
// RTL's bit-level arithmetic against an independent model: the iteration count, every
// pulse and its clock, the end, and when the block's words may go. The words come one bit
// per clock, the bit the DDA asks for (bit_o), as the player's multiplexers and the
// decoder's turning registers give them; they are scrambled once words_o falls, so a DDA
// that still read them would differ.
#include <gtest/gtest.h>

#include <memory>
#include <random>
#include <sstream>

#include "Vdda_serial_w16.h"
#include "Vdda_serial_w4.h"
#include "Vdda_serial_w6.h"
#include "arc_cases.h"
#include "arc_geometry.h"
#include "dda_serial.h"
#include "verilated.h"
#include "verilated_clock.h"

namespace ncinterp {
namespace {

using circle_study::QuadrantArc;

using test::clock_edge;

// A block as the player loads it (dda_serial's load inputs).
struct Block {
  bool line = false;
  unsigned k = 0;
  uint32_t x = 0, y = 0, cnt_x = 0, cnt_y = 0;
  bool grow_x = false, grow_y = false, dir_x = false, dir_y = false;
  std::string describe() const {
    std::ostringstream o;
    o << (line ? "line" : "arc") << " k " << k << " x " << x << " y " << y << " cnt " << cnt_x
      << "/" << cnt_y << " grow " << grow_x << grow_y;
    return o.str();
  }
};

Block arc_block(const QuadrantArc& a, unsigned w) {
  const ArcWords words = a.words();
  const ArcGeometry g = arc_geometry(words, w);
  Block b;
  b.k = g.k;
  b.x = static_cast<uint32_t>(g.x0);
  b.y = static_cast<uint32_t>(g.y0);
  b.cnt_x = g.cnt_x;
  b.cnt_y = g.cnt_y;
  b.grow_x = g.grow_x;
  b.grow_y = g.grow_y;
  b.dir_x = !words.dx_neg;
  b.dir_y = !words.dy_neg;
  return b;
}

Block line_block(int64_t dx, int64_t dy, std::mt19937_64& rng) {
  Block b;
  b.line = true;
  b.cnt_x = static_cast<uint32_t>(dx < 0 ? -dx : dx);
  b.cnt_y = static_cast<uint32_t>(dy < 0 ? -dy : dy);
  while (b.k < 32 && ((b.cnt_x | b.cnt_y) >> b.k) != 0) ++b.k;
  b.x = static_cast<uint32_t>(rng());  // not read for a line
  b.y = static_cast<uint32_t>(rng());
  b.dir_x = dx >= 0;
  b.dir_y = dy >= 0;
  return b;
}

// The words' bits of this clock: bit bit_o of each (0 from bit w on).
struct Words {
  uint32_t x = 0, y = 0, cnt_x = 0, cnt_y = 0;
};

template <typename Model>
void drive_words(Model& m, const Words& v, unsigned w) {
  const unsigned bit = m.bit_o;
  const auto at = [&](uint32_t word) { return bit < w && ((word >> bit) & 1u); };
  m.x_bit_i = at(v.x);
  m.y_bit_i = at(v.y);
  m.cnt_x_bit_i = at(v.cnt_x);
  m.cnt_y_bit_i = at(v.cnt_y);
}

// Loads one block into the verilated DDA and its twin and plays it to its end with strobes
// of a random density (at least min_percent); compares every output every clock. Also
// checks, independently of the twin, that each axis emits exactly its count of pulses.
template <typename Model>
::testing::AssertionResult lockstep(Model& m, unsigned w, const Block& b, std::mt19937_64& rng,
                                    unsigned min_percent = 1) {
  const uint32_t mask = static_cast<uint32_t>((uint64_t{1} << w) - 1);
  SerialDda golden(w);
  if (b.line)
    golden.load_line(b.k, b.cnt_x, b.cnt_y, b.dir_x, b.dir_y);
  else
    golden.load(ArcGeometry{b.x, b.y, 0, 0, b.cnt_x, b.cnt_y, b.grow_x, b.grow_y, b.k,
                            TapeError::kNone},
                b.dir_x, b.dir_y);
  m.load_i = 1;
  m.line_i = b.line;
  m.k_i = static_cast<uint8_t>(b.k);
  Words words{b.x & mask, b.y & mask, b.cnt_x & mask, b.cnt_y & mask};
  drive_words(m, words, w);
  m.grow_x_i = b.grow_x;
  m.grow_y_i = b.grow_y;
  m.dir_x_i = b.dir_x;
  m.dir_y_i = b.dir_y;
  m.strobe_i = rng() % 2;  // ignored at a load edge
  m.eval();
  if (m.iterate_o || m.carry_x_o || m.carry_y_o)
    return ::testing::AssertionFailure() << b.describe() << ": an iteration at the load edge";
  clock_edge(m);
  m.load_i = 0;
  const unsigned strobe_percent = min_percent + static_cast<unsigned>(rng() % (101 - min_percent));
  uint64_t pulses[2] = {0, 0};
  int after_done = 3;
  for (uint64_t clock = 1; clock < (uint64_t{1} << 24); ++clock) {
    m.strobe_i = rng() % 100 < strobe_percent;
    if (!golden.words()) {
      words = Words{static_cast<uint32_t>(rng()) & mask, static_cast<uint32_t>(rng()) & mask,
                    static_cast<uint32_t>(rng()) & mask, static_cast<uint32_t>(rng()) & mask};
      m.k_i = static_cast<uint8_t>(rng() % (w + 1));
      m.line_i = rng() % 2;
    }
    drive_words(m, words, w);
    m.eval();
    std::ostringstream where;
    where << b.describe() << ", clock " << clock << ": ";
    if (m.done_o != golden.done())
      return ::testing::AssertionFailure() << where.str() << "done_o RTL " << int(m.done_o);
    if (m.words_o != golden.words())
      return ::testing::AssertionFailure() << where.str() << "words_o RTL " << int(m.words_o);
    const SerialDda::Edge e = golden.edge(m.strobe_i);
    if (m.iterate_o != e.iterate)
      return ::testing::AssertionFailure() << where.str() << "iterate_o RTL " << int(m.iterate_o);
    if (m.carry_x_o != e.x || m.carry_y_o != e.y)
      return ::testing::AssertionFailure() << where.str() << "carry RTL (" << int(m.carry_x_o)
                                           << ", " << int(m.carry_y_o) << ") golden (" << e.x
                                           << ", " << e.y << ")";
    clock_edge(m);
    pulses[0] += e.x;
    pulses[1] += e.y;
    if (m.step_x_o != e.x || m.step_y_o != e.y || m.dir_x_o != b.dir_x || m.dir_y_o != b.dir_y)
      return ::testing::AssertionFailure() << where.str() << "step/dir after the edge";
    if (golden.done() && --after_done == 0) {
      if (pulses[0] != b.cnt_x || pulses[1] != b.cnt_y)
        return ::testing::AssertionFailure() << b.describe() << ": pulses " << pulses[0] << "/"
                                             << pulses[1];
      return ::testing::AssertionSuccess();
    }
  }
  return ::testing::AssertionFailure() << b.describe() << ": did not finish";
}

template <typename Model>
std::unique_ptr<Model> make_model(VerilatedContext* ctx) {
  auto m = std::make_unique<Model>(ctx);
  test::reset(*m);
  return m;
}

TEST(DdaSerialLockstep, EveryArcAndLineOfAFourBitRegister) {
  auto ctx = std::make_unique<VerilatedContext>();
  auto m = make_model<Vdda_serial_w4>(ctx.get());
  std::mt19937_64 rng(41);
  int arcs = 0;
  for (int64_t x0 = -15; x0 <= 15; ++x0)
    for (int64_t y0 = -15; y0 <= 15; ++y0)
      for (int64_t x1 = -15; x1 <= 15; ++x1)
        for (int64_t y1 = -15; y1 <= 15; ++y1)
          for (bool ccw : {false, true}) {
            const QuadrantArc a{x0, y0, x1, y1, ccw};
            if (check_arc(a.words(), 4) != TapeError::kNone) continue;
            ASSERT_TRUE(lockstep(*m, 4, arc_block(a, 4), rng));
            ++arcs;
          }
  EXPECT_GT(arcs, 2000);
  for (int64_t dx = -15; dx <= 15; ++dx)
    for (int64_t dy = -15; dy <= 15; ++dy) ASSERT_TRUE(lockstep(*m, 4, line_block(dx, dy, rng), rng));
}

// W = 6: a pass is P = 8 clocks, its bits 6 and 7 are 0.
TEST(DdaSerialLockstep, RandomArcsAndLinesWithPassesLongerThanW) {
  auto ctx = std::make_unique<VerilatedContext>();
  auto m = make_model<Vdda_serial_w6>(ctx.get());
  std::mt19937_64 rng(42);
  int arcs = 0;
  for (int t = 0; t < 3000; ++t) {
    const QuadrantArc a = circle_study::random_arc(rng, 63);
    if (check_arc(a.words(), 6) == TapeError::kNone) {
      ASSERT_TRUE(lockstep(*m, 6, arc_block(a, 6), rng));
      ++arcs;
    }
    ASSERT_TRUE(lockstep(*m, 6, line_block(int64_t(rng() % 127) - 63, int64_t(rng() % 127) - 63, rng),
                         rng));
  }
  EXPECT_GT(arcs, 1000);
}

TEST(DdaSerialLockstep, RandomArcsAndLinesAtW16) {
  auto ctx = std::make_unique<VerilatedContext>();
  auto m = make_model<Vdda_serial_w16>(ctx.get());
  std::mt19937_64 rng(43);
  int arcs = 0;
  // The quadrants of the largest and the smallest radius and lines of every length, at
  // full strobe rate (2^16 iterations take 2^21 clocks)...
  for (int t = 0; t < 6; ++t) {
    const QuadrantArc a = circle_study::full_quadrant(t < 4 ? 1 : 65535, t % 4, t % 2 == 0);
    ASSERT_TRUE(lockstep(*m, 16, arc_block(a, 16), rng, 100));
  }
  for (int t = 0; t < 20; ++t) {
    const int64_t top = int64_t{1} << (rng() % 17);
    ASSERT_TRUE(lockstep(*m, 16, line_block(int64_t(rng() % top) * (t % 2 ? 1 : -1),
                                            int64_t(rng() % top) * (t % 4 < 2 ? 1 : -1), rng),
                         rng, 100));
  }
  // ... and random arcs and short lines at any strobe rate.
  for (int t = 0; t < 200; ++t) {
    const QuadrantArc a = circle_study::random_arc(rng, t % 2 ? 2047 : 100);
    if (check_arc(a.words(), 16) == TapeError::kNone) {
      ASSERT_TRUE(lockstep(*m, 16, arc_block(a, 16), rng, 20));
      ++arcs;
    }
    ASSERT_TRUE(lockstep(*m, 16, line_block(int64_t(rng() % 2001) - 1000,
                                            int64_t(rng() % 2001) - 1000, rng),
                         rng, 20));
  }
  EXPECT_GT(arcs, 150);
}

}  // namespace
}  // namespace ncinterp
