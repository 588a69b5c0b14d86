// Module-level lock step of the verilated tape decoder (rtl/tape_decoder.sv, its frame
// input, word parser and arc preparation) against GoldenTapeDecoder, every clock: the
// reader's ready, the held block and every field of it, the end, and the error with its code,
// block and offset. Random word-heavy tapes: now and then a number over its word's limit,
// a stray character, a wrong fraction or a parity error, small arcs; the reader and the
// block buffer at random speeds (the handshakes stall both ways). The decoder both parallel
// and bit-serial (BitSerial: a digit's x10 + d is a pass of NumWidth clocks, and its
// limit's verdict comes at the pass's end), at the default widths and at narrow ones.
#include <gtest/gtest.h>

#include <memory>
#include <type_traits>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include "Vtape_decoder.h"
#include "Vtape_decoder_lines.h"
#include "Vtape_decoder_narrow.h"
#include "Vtape_decoder_serial.h"
#include "Vtape_decoder_serial_narrow.h"
#include "bit_length.h"
#include "tape_decoder.h"
#include "verilated.h"
#include "verilated_clock.h"

namespace ncinterp {
namespace {

// The widths of a verilated flavour (its -G parameters in CMakeLists.txt).
InterpConfig config(bool narrow, bool bit_serial) {
  InterpConfig c;
  if (narrow) {
    c.inc_width = 6;
    c.feed_width = 8;
    c.seq_width = 7;
    c.offset_width = 12;
    c.modulus_width = 12;  // S saturates at 2^13 - 1, bit-serial 2^9 - 1 (CMakeLists.txt)
  }
  c.arch = bit_serial ? Arch::kSerial : Arch::kParallel;
  return c;
}

// A number of a word whose register has `bits` bits, with `frac` fraction digits on tape:
// one in 20 drawn below 2^(bits + 1) (so about half of those are over the word's limit),
// the others within it.
std::string number(std::mt19937_64& rng, unsigned bits, unsigned frac) {
  const uint64_t v = rng() % (uint64_t{rng() % 20 == 0 ? 2u : 1u} << bits);
  std::string s = std::to_string(v);
  if (frac == 0) return s;
  if (s.size() <= frac) s = std::string(frac + 1 - s.size(), '0') + s;
  return s.substr(0, s.size() - frac) + "." + s.substr(s.size() - frac);
}

// A tape of random blocks in the strict syntax, with faults now and then (each block has
// a small chance to break the syntax somewhere), as frames with even parity.
std::vector<uint8_t> random_tape(std::mt19937_64& rng, const InterpConfig& c) {
  const auto chance = [&](unsigned percent) { return rng() % 100 < percent; };
  std::string t = "%\n";
  bool arc = false;  // the modal motion: arcs get small words (short preparations)
  const int blocks = 2 + static_cast<int>(rng() % 8);
  for (int b = 0; b < blocks; ++b) {
    if (chance(60)) t += "N" + number(rng, c.seq_width, 0) + " ";
    if (chance(50)) {
      static const char* const codes[] = {"01", "1", "02", "03", "17", "01", "91", "00", "93", "2",
                                          "09", "61", "99", "64", "100", "123"};
      const std::string g = codes[rng() % (chance(90) ? 12 : 16)];
      t += "G" + g + " ";
      if (g == "01" || g == "1" || g == "00") arc = false;
      if (g == "02" || g == "03" || g == "2") arc = true;
    }
    const unsigned bits = arc ? std::min(c.inc_width, 9u) : c.inc_width;
    for (const char* axis : {"X", "Y", "I", "J"}) {
      if (!chance(arc || axis[0] == 'X' || axis[0] == 'Y' ? 70 : 10)) continue;
      t += axis;
      if (chance(40)) t += chance(50) ? "-" : "+";
      t += number(rng, bits, c.frac_digits);
    }
    if (chance(60)) t += "F" + number(rng, c.feed_width, c.feed_frac_digits);
    // An M word that acts (a still block without X, Y, I, J), now and then two (refused),
    // or one the interpolator does not have (M04).
    for (int m = 0; m < 2 && chance(m == 0 ? 25 : 10); ++m) {
      static const char* const codes[] = {"00", "0", "01", "03", "3", "05", "5", "04"};
      t += std::string(" M") + codes[rng() % (chance(95) ? 7 : 8)];
    }
    if (chance(3)) {  // a fault: a stray character somewhere in the block
      static const std::string stray = "XYZ+-.0123456789 \r%(A";
      const size_t at = 2 + rng() % (t.size() - 1);
      t.insert(at, 1, stray[rng() % stray.size()]);
    }
    if (chance(5)) t += "(comment " + std::to_string(b) + ")";
    t += chance(1) ? "" : "\n";
  }
  if (chance(90)) t += "M02\n%\n";
  std::vector<uint8_t> frames;
  for (char ch : t) {
    uint8_t f = static_cast<uint8_t>(ch) & 0x7f;
    if (__builtin_parity(f)) f |= 0x80;
    if (rng() % 1000 == 0) f ^= 0x40;  // a parity error
    frames.push_back(f);
  }
  return frames;
}

using test::clock_edge;

// Bits [lo, lo + width) of a verilated port: a VlWide array of 32-bit words, or an integer.
template <typename Port>
uint64_t bits(const Port& port, unsigned lo, unsigned width) {
  uint64_t v = 0;
  for (unsigned b = 0; b < width; ++b) {
    const unsigned at = lo + b;
    uint64_t bit;
    if constexpr (std::is_integral_v<Port>)
      bit = (static_cast<uint64_t>(port) >> at) & 1;
    else
      bit = (port[at / 32] >> (at % 32)) & 1;
    v |= bit << b;
  }
  return v;
}

// The held block's fields, read from blk_o in sw/host/tape/block_record.def's order (the last
// field in the lowest bits).
struct HeldBlock {
  uint64_t n, motion, stop, optional_stop, tool_on, tool_off, dx_neg, dx, dy_neg, dy, i, j,
      step_over, iterations, step;
};
template <typename Port>
HeldBlock unpack(const Port& p, const InterpConfig& c, unsigned step_width) {
  const unsigned w = c.inc_width, k_width = bit_length(w);  // $clog2(W + 1)
  HeldBlock b;
  unsigned at = 0;
  const auto take = [&](unsigned width) {
    const uint64_t v = bits(p, at, width);
    at += width;
    return v;
  };
  b.step = take(step_width);
  b.iterations = take(w + 1);
  take(2 + k_width);  // grow_y, grow_x, k: set by the arc preparation (test_circle_rtl_lockstep)
  b.step_over = take(1);
  b.j = take(w);
  b.i = take(w);
  b.dy = take(w);
  b.dy_neg = take(1);
  b.dx = take(w);
  b.dx_neg = take(1);
  b.tool_off = take(1);
  b.tool_on = take(1);
  b.optional_stop = take(1);
  b.stop = take(1);
  b.motion = take(2);
  b.n = take(c.seq_width);
  return b;
}

// The RTL's outputs against the golden decoder's state after the same edge.
template <typename Model>
::testing::AssertionResult same(const Model& m, const GoldenTapeDecoder& g, const InterpConfig& c,
                                unsigned step_width) {
  using State = GoldenTapeDecoder::State;
  const DecodedBlock b = g.block();
  std::ostringstream diff;
  const auto check = [&](const char* name, uint64_t rtl, uint64_t golden) {
    if (rtl != golden && diff.tellp() == 0)
      diff << name << ": RTL " << rtl << ", golden " << golden;
  };
  check("frame_ready_o", m.frame_ready_o, g.ready());
  check("blk_valid_o", m.blk_valid_o, g.state() == State::kHold);
  check("end_o", m.end_o, g.state() == State::kEnd);
  check("err_o", m.err_o, g.state() == State::kError);
  if (m.blk_valid_o) {
    const HeldBlock h = unpack(m.blk_o, c, step_width);
    check("blk_o.n", h.n, b.n);
    check("blk_o.motion", h.motion, b.motion);
    check("blk_o.stop", h.stop, b.stop);
    check("blk_o.optional_stop", h.optional_stop, b.optional_stop);
    check("blk_o.tool_on", h.tool_on, b.tool_on);
    check("blk_o.tool_off", h.tool_off, b.tool_off);
    check("blk_o.dx", h.dx, b.dx);
    check("blk_o.dx_neg", h.dx_neg, b.dx_neg);
    check("blk_o.dy", h.dy, b.dy);
    check("blk_o.dy_neg", h.dy_neg, b.dy_neg);
    // Without circle mode I and J are not kept (the golden decoder reads them all the same).
    check("blk_o.i", h.i, c.circle_mode ? b.i : 0);
    check("blk_o.j", h.j, c.circle_mode ? b.j : 0);
    check("blk_o.step", h.step, b.step);
    check("blk_o.step_over", h.step_over, b.step_over);
    check("blk_o.iterations", h.iterations, b.iterations);
  }
  if (m.err_o) {
    check("err_code_o", m.err_code_o, static_cast<uint64_t>(g.error_code()));
    check("err_block_o", m.err_block_o, g.error_block());
    check("err_offset_o", m.err_offset_o, g.error_offset());
  }
  if (diff.tellp() == 0) return ::testing::AssertionSuccess();
  // With the states, which tell a late error from a wrong one.
  return ::testing::AssertionFailure()
         << diff.str() << " (golden state " << int(g.state()) << ", error code "
         << int(g.error_code()) << "; RTL err_o " << int(m.err_o) << ", err_code_o "
         << int(m.err_code_o) << ", blk_valid_o " << int(m.blk_valid_o) << ")";
}

// How the tapes ended: a program decoded to its end, an error (by code).
struct Outcomes {
  int ended = 0, held_blocks = 0;
  int saturated_steps = 0;  // held blocks whose S reached 2^StepWidth (step_over)
  int m_blocks = 0;         // held blocks with an M word that acts (M00, M01, M03, M05)
  int errors[16] = {0};
};

// Plays `tapes` random tapes through the verilated decoder and its twin in lock step.
template <typename Model>
::testing::AssertionResult lockstep(const InterpConfig& c, unsigned step_width, int tapes,
                                   uint64_t seed, Outcomes& out) {
  std::mt19937_64 rng(seed);
  auto ctx = std::make_unique<VerilatedContext>();
  Model m(ctx.get());
  GoldenTapeDecoder g(c);
  for (int t = 0; t < tapes; ++t) {
    const std::vector<uint8_t> frames = random_tape(rng, c);
    // The reader offers a frame in this share of clocks; the buffer is free in that share.
    const unsigned offer_percent = std::vector<unsigned>{100, 50, 3}[rng() % 3];
    const unsigned free_percent = std::vector<unsigned>{100, 30}[rng() % 2];
    m.rst_ni = 0;
    // The rapid step as the decoder's port holds it (ModulusWidth bits).
    m.rapid_step_i = c.rapid_step & ((uint64_t{1} << c.modulus_width) - 1);
    m.frame_valid_i = 0;
    m.tape_end_i = 0;
    m.blk_ready_i = 0;
    m.eval();  // the model's first evaluation sees no edge
    clock_edge(m);
    m.rst_ni = 1;
    m.eval();
    g.reset();
    size_t next = 0;
    for (uint64_t clock = 1; clock < 3'000'000; ++clock) {
      const bool offer = next < frames.size() && rng() % 100 < offer_percent;
      InterpInputs in;
      in.frame_valid = offer;
      in.frame = offer ? frames[next] : 0;
      in.tape_end = next == frames.size();
      const bool free = rng() % 100 < free_percent;
      if (free && g.state() == GoldenTapeDecoder::State::kHold) {
        ++out.held_blocks;
        const DecodedBlock b = g.block();
        out.saturated_steps += b.step_over;
        out.m_blocks += b.stop || b.optional_stop || b.tool_on || b.tool_off;
      }
      if (offer && m.frame_ready_o) ++next;
      m.frame_valid_i = in.frame_valid;
      m.frame_i = in.frame;
      m.tape_end_i = in.tape_end;
      m.blk_ready_i = free;
      g.edge(in, free);
      clock_edge(m);
      const ::testing::AssertionResult r = same(m, g, c, step_width);
      if (!r)
        return ::testing::AssertionFailure() << "tape " << t << " (seed " << seed << "), clock "
                                             << clock << ": " << r.message();
      if (m.err_o) {
        ++out.errors[m.err_code_o & 15];
        break;
      }
      if (m.end_o && next == frames.size()) {
        ++out.ended;
        break;
      }
    }
  }
  return ::testing::AssertionSuccess();
}

// Enough of every kind of run that the comparison covered them: programs to their end,
// blocks handed over, and words over their limit (the bit-serial limit check's verdict).
void expect_coverage(const Outcomes& o) {
  EXPECT_GT(o.ended, 100);
  EXPECT_GT(o.held_blocks, 2000);
  EXPECT_GT(o.m_blocks, 200);
  EXPECT_GT(o.errors[static_cast<int>(TapeError::kValueTooWide)], 100);
  EXPECT_GT(o.errors[static_cast<int>(TapeError::kMalformedNumber)], 20);
}

TEST(DecoderLockstep, ParallelEqualsGoldenEveryClock) {
  Outcomes o;
  EXPECT_TRUE(lockstep<Vtape_decoder>(config(false, false), 49, 2000, 1, o));
  expect_coverage(o);
}

TEST(DecoderLockstep, BitSerialEqualsGoldenEveryClock) {
  Outcomes o;
  EXPECT_TRUE(lockstep<Vtape_decoder_serial>(config(false, true), 44, 2000, 2, o));
  expect_coverage(o);
}

// Narrow: the feed step S saturates too (at 2^13 - 1, bit-serial 2^9 - 1).
TEST(DecoderLockstep, ParallelEqualsGoldenEveryClockAtNarrowWidths) {
  Outcomes o;
  EXPECT_TRUE(lockstep<Vtape_decoder_narrow>(config(true, false), 13, 2000, 3, o));
  expect_coverage(o);
  EXPECT_GT(o.saturated_steps, 50);
}

TEST(DecoderLockstep, BitSerialEqualsGoldenEveryClockAtNarrowWidths) {
  Outcomes o;
  EXPECT_TRUE(lockstep<Vtape_decoder_serial_narrow>(config(true, true), 9, 2000, 4, o));
  expect_coverage(o);
  EXPECT_GT(o.saturated_steps, 50);
}

// Without circle mode (the iCEstick's serial core): every G02/G03 word is refused with
// its own code, at the word, and lines play as with circle mode.
TEST(DecoderLockstep, LinesOnlyEqualsGoldenEveryClock) {
  Outcomes o;
  InterpConfig c = config(false, true);
  c.circle_mode = false;
  c.misc_functions = false;
  EXPECT_TRUE(lockstep<Vtape_decoder_lines>(c, 44, 2000, 5, o));
  EXPECT_GT(o.errors[static_cast<int>(TapeError::kNoCircleMode)], 100);
  EXPECT_GT(o.errors[static_cast<int>(TapeError::kUnsupportedCode)], 100);
  EXPECT_GT(o.held_blocks, 200);
  EXPECT_EQ(o.m_blocks, 0);
}

}  // namespace
}  // namespace ncinterp
