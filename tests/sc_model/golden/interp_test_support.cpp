// Test support: line tape text, output recorder, program checks (see the header).
#include "interp_test_support.h"

#include "bit_length.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <map>
#include <sstream>

#include "tape.h"

namespace ncinterp::test {

namespace {

uint64_t ceil_div(uint64_t a, uint64_t b) { return (a + b - 1) / b; }

}  // namespace

std::string line_tape_text(const std::vector<LineBlock>& blocks, unsigned frac_digits,
                           unsigned feed_frac_digits) {
  tape::Program program;
  for (const LineBlock& b : blocks) {
    tape::Block block;
    block.n = b.n;
    block.dx = b.dx;
    block.dy = b.dy;
    block.feed = b.feed;
    program.blocks.push_back(block);
  }
  tape::Format format;
  format.frac_digits = frac_digits;
  format.feed_frac_digits = feed_frac_digits;
  return tape::format_program(program, format);
}

std::vector<uint8_t> frames_of(std::string_view text) { return tape::add_parity(text); }

void OutputRecorder::observe(uint64_t cycle, const InterpOutputs& o) {
  cycles = cycle;
  if (load_.loads(o)) starts.push_back({cycle, o.block_n, o.feed_saturated});
  if (o.busy) ++busy_cycles;
  if (o.step_x) pulses.push_back({cycle, o.block_n, 0, o.dir_x, o.pos_x, o.pos_y});
  if (o.step_y) pulses.push_back({cycle, o.block_n, 1, o.dir_y, o.pos_x, o.pos_y});
  load_.keep(o);
  last = o;
}

::testing::AssertionResult check_line_program(const std::vector<LineBlock>& blocks,
                                              const OutputRecorder& rec) {
  struct Expect {
    int64_t x0, y0, dx, dy;
    int64_t count[2][2] = {{0, 0}, {0, 0}};  // [axis][plus]
  };
  std::map<uint32_t, Expect> by_n;
  int64_t x = 0, y = 0;
  for (const LineBlock& b : blocks) {
    if (by_n.count(b.n)) return ::testing::AssertionFailure() << "duplicate N" << b.n << " in test";
    by_n[b.n] = Expect{x, y, b.dx, b.dy};
    x += b.dx;
    y += b.dy;
  }
  for (const auto& p : rec.pulses) {
    auto it = by_n.find(p.block);
    if (it == by_n.end())
      return ::testing::AssertionFailure()
             << "pulse at cycle " << p.cycle << " while block_n = " << p.block
             << ", which is not a good block of the program";
    Expect& e = it->second;
    ++e.count[p.axis][p.plus ? 1 : 0];
    // Distance of the pulse position to the block's chord segment, against the L1 bound.
    const double dx = static_cast<double>(e.dx), dy = static_cast<double>(e.dy);
    const double px = static_cast<double>(p.x - e.x0), py = static_cast<double>(p.y - e.y0);
    const double len = std::hypot(dx, dy);
    double dist;
    if (len == 0) {
      dist = std::hypot(px, py);
    } else {
      double t = (px * dx + py * dy) / (len * len);
      t = t < 0 ? 0 : (t > 1 ? 1 : t);
      dist = std::hypot(px - t * dx, py - t * dy);
    }
    const double bound = len == 0 ? 0.0 : (std::fabs(dx) + std::fabs(dy)) / (2 * len);
    if (dist > bound + 1e-9)
      return ::testing::AssertionFailure()
             << "block N" << p.block << " (" << e.dx << ", " << e.dy << "): pulse at cycle "
             << p.cycle << " puts the tool at (" << p.x - e.x0 << ", " << p.y - e.y0
             << ") relative to the block start, " << dist << " BLU from the chord (bound "
             << bound << ")";
  }
  for (const auto& [n, e] : by_n) {
    const int64_t want[2] = {e.dx, e.dy};
    for (int a = 0; a < 2; ++a) {
      const int64_t plus = want[a] > 0 ? want[a] : 0, minus = want[a] < 0 ? -want[a] : 0;
      if (e.count[a][1] != plus || e.count[a][0] != minus)
        return ::testing::AssertionFailure()
               << "block N" << n << " axis " << "XY"[a] << ": " << e.count[a][1] << " plus and "
               << e.count[a][0] << " minus pulses, programmed " << want[a];
    }
  }
  if (rec.last.pos_x != x || rec.last.pos_y != y)
    return ::testing::AssertionFailure() << "final position (" << rec.last.pos_x << ", "
                                         << rec.last.pos_y << "), programmed (" << x << ", " << y
                                         << ")";
  return ::testing::AssertionSuccess();
}

InterpOutputs run_golden(GoldenInterp& dut, const std::vector<uint8_t>& frames,
                         uint64_t cycles_per_frame, uint64_t max_cycles, OutputRecorder& rec) {
  FrameSource source(frames, cycles_per_frame);
  rec.observe(0, dut.outputs());
  while (!dut.outputs().done && !dut.outputs().error && dut.cycle() < max_cycles) {
    const bool ready = dut.outputs().frame_ready;
    dut.tick(source.inputs());
    source.clock(ready);
    rec.observe(dut.cycle(), dut.outputs());
  }
  return dut.outputs();
}

std::vector<uint8_t> BadTape::frames() const {
  std::vector<uint8_t> f = frames_of(text);
  if (code == TapeError::kParity) f.at(offset) ^= 0x80;
  return f;
}

void PrintTo(const BadTape& t, std::ostream* os) { *os << t.name; }

std::vector<BadTape> bad_tapes() {
  const std::string head = "%\nG17 G21 G91 G93\nN10 G01 X0.005 Y-0.003 F100000.000\n";
  const std::vector<LineBlock> good = {{10, 5, -3, 100000000}};
  std::vector<BadTape> t;
  auto at = [&](const std::string& text, const std::string& what, size_t from = 0) {
    return text.find(what, from);
  };
  std::string s;
  s = head + "N20 G01 X0.007 Y0.002\nM02\n%\n";
  t.push_back({"parity", s, TapeError::kParity, 20, at(s, "7 Y"), good});
  s = head + "N20 G01 Q0.007\nM02\n%\n";
  t.push_back({"unknown_letter", s, TapeError::kUnknownCharacter, 20, at(s, "Q"), good});
  s = head + "N20 G01 X65.536\nM02\n%\n";
  t.push_back({"too_wide", s, TapeError::kValueTooWide, 20, at(s, "536") + 2, good});
  s = head + "N20 G01 X0.001 N30 G01 X0.002\nM02\n%\n";
  t.push_back({"missing_eob", s, TapeError::kMissingEndOfBlock, 20, at(s, "N30"), good});
  s = head + "N20 G01 X0.0";
  t.push_back({"truncated", s, TapeError::kTruncatedTape, 20, s.size(), good});
  s = head + "M02\nN30 X0.001\n%\n";
  t.push_back({"after_end", s, TapeError::kBlockAfterEnd, 10, at(s, "N30"), good});
  s = head + "N20 G01 X1.00 Y0.000\nM02\n%\n";
  t.push_back({"short_fraction", s, TapeError::kMalformedNumber, 20, at(s, "X1.00"), good});
  s = head + "N20 G01 X1.0000\nM02\n%\n";
  t.push_back({"long_fraction", s, TapeError::kMalformedNumber, 20, at(s, "0000", at(s, "N20")) + 3, good});
  s = head + "N20 G01 X12\nM02\n%\n";
  t.push_back({"no_point", s, TapeError::kMalformedNumber, 20, at(s, "X12"), good});
  s = head + "N20 G01 X1-.000\nM02\n%\n";
  t.push_back({"late_sign", s, TapeError::kMalformedNumber, 20, at(s, "-."), good});
  s = head + "N20 G90 X1.000\nM02\n%\n";
  t.push_back({"g90", s, TapeError::kUnsupportedCode, 20, at(s, "G90"), good});
  s = head + "N20 G04 X1.000\nM02\n%\n";
  t.push_back({"g04", s, TapeError::kUnsupportedCode, 20, at(s, "G04"), good});
  s = head + "N20 G03 X1.000 Y1.000 I1.000 J0.000\nM02\n%\n";
  t.push_back({"arc_leaves_its_quadrant", s, TapeError::kArcCrossesQuadrant, 20, at(s, "\n", at(s, "N20")), good});
  s = head + "N20 M04\nM02\n%\n";  // spindle counter-clockwise: the tool pin has one way
  t.push_back({"m04", s, TapeError::kUnsupportedCode, 20, at(s, "M04"), good});
  s = head + "N20 M03 M00\nM02\n%\n";  // one M word per block
  t.push_back({"two_m_words", s, TapeError::kUnsupportedCode, 20, at(s, "M00"), good});
  s = head + "N1048576 X0.001\nM02\n%\n";
  t.push_back({"n_too_wide", s, TapeError::kValueTooWide, 10, at(s, "1048576") + 6, good});
  s = head + "N20 X0.001 F4294967.296\nM02\n%\n";
  t.push_back({"f_too_wide", s, TapeError::kValueTooWide, 20, at(s, "4294967.296") + 10, good});
  s = head + "N20 X0.001 %\n";
  t.push_back({"percent_in_block", s, TapeError::kMissingEndOfBlock, 20, at(s, "%", 3), good});
  s = head + "%\n";
  t.push_back({"percent_before_end", s, TapeError::kTruncatedTape, 10, at(s, "%", 3), good});
  s = "%\nG17 G21 G91 G93\nN10 G01 X0.005\nM02\n%\n";
  t.push_back({"missing_feed", s, TapeError::kMissingFeed, 10, at(s, "\n", at(s, "N10")), {}});
  s = head + "N20 X0.001 F0.000\nM02\n%\n";
  t.push_back({"feed_zero", s, TapeError::kMissingFeed, 20, at(s, "\n", at(s, "N20")), good});
  s = head + "N20 x0.001\nM02\n%\n";
  t.push_back({"lower_case", s, TapeError::kUnknownCharacter, 20, at(s, "x"), good});
  s = head + "N20 (spaces do not end a number, a comment does)5\nM02\n%\n";
  t.push_back({"digit_without_letter", s, TapeError::kMalformedNumber, 20, at(s, ")5") + 1, good});
  s = std::string("") + "";
  t.push_back({"empty_tape", s, TapeError::kTruncatedTape, 0, 0, {}});
  s = std::string("\0\0\0", 3) + "no program here";
  t.push_back({"no_start", s, TapeError::kTruncatedTape, 0, s.size(), {}});
  s = head + "N20 (never closed\nM02\n%\n";
  t.push_back({"open_comment", s, TapeError::kTruncatedTape, 20, s.size(), good});
  return t;
}


std::vector<LineBlock> random_line_program(std::mt19937_64& rng, unsigned inc_width,
                                           uint64_t modulus) {
  const int64_t max = (int64_t{1} << inc_width) - 1;
  const int64_t medium = std::min<int64_t>(max, 4095);
  std::uniform_int_distribution<int> nblocks(1, 8), kind(0, 19);
  std::vector<LineBlock> prog;
  const int n = nblocks(rng);
  for (int i = 0; i < n; ++i) {
    // Full-width moves cost 2^W clocks, so they are rarer than small ones.
    auto value = [&]() -> int64_t {
      switch (kind(rng)) {
        case 0: case 1: return 0;
        case 2: return max;
        case 3: return -max;
        case 4: return std::uniform_int_distribution<int64_t>(-max, max)(rng);
        case 5: case 6: case 7: case 8:
          return std::uniform_int_distribution<int64_t>(-medium, medium)(rng);
        default: return std::uniform_int_distribution<int64_t>(-300, 300)(rng);
      }
    };
    LineBlock b{static_cast<uint32_t>(10 * (i + 1)), value(), value(), 0};
    const uint64_t kpow = 1ull << bit_length(static_cast<uint64_t>(std::abs(b.dx) | std::abs(b.dy)));
    const uint64_t clocks = std::uniform_int_distribution<uint64_t>(1, 3 * kpow + 8)(rng);
    b.feed = std::min<uint64_t>(ceil_div(modulus, clocks), 0xffffffffull);
    prog.push_back(b);
  }
  return prog;
}


}  // namespace ncinterp::test
