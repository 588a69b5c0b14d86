// Test support: line tape text, output recorder, program checks (see the header).
#include "interp_test_support.h"

#include <cmath>
#include <cstdlib>
#include <map>
#include <sstream>

namespace ncinterp::test {

namespace {

std::string fixed(int64_t value, unsigned frac_digits) {
  int64_t scale = 1;
  for (unsigned i = 0; i < frac_digits; ++i) scale *= 10;
  const uint64_t mag = static_cast<uint64_t>(value < 0 ? -value : value);
  std::string frac = std::to_string(mag % static_cast<uint64_t>(scale));
  frac.insert(0, frac_digits - frac.size(), '0');
  return std::string(value < 0 ? "-" : "") + std::to_string(mag / static_cast<uint64_t>(scale)) +
         "." + frac;
}

}  // namespace

std::string line_tape_text(const std::vector<LineBlock>& blocks, unsigned frac_digits,
                           unsigned feed_frac_digits) {
  std::string text = "%\nG17 G21 G91 G93\n";
  for (const LineBlock& b : blocks) {
    text += "N" + std::to_string(b.n) + " G01 X" + fixed(b.dx, frac_digits) + " Y" +
            fixed(b.dy, frac_digits) + " F" + fixed(static_cast<int64_t>(b.feed), feed_frac_digits) +
            "\n";
  }
  text += "M02\n%\n";
  return text;
}

std::vector<uint8_t> frames_of(std::string_view text) {
  std::vector<uint8_t> frames;
  for (char c : text) {
    const uint8_t ch = static_cast<uint8_t>(c) & 0x7f;
    frames.push_back(static_cast<uint8_t>(ch | (__builtin_parity(ch) ? 0x80 : 0)));
  }
  return frames;
}

void OutputRecorder::observe(uint64_t cycle, const InterpOutputs& o) {
  cycles = cycle;
  if (o.busy && (!was_busy_ || o.block_n != last.block_n))
    starts.push_back({cycle, o.block_n, o.feed_saturated});
  if (o.busy) ++busy_cycles;
  if (o.step_x) pulses.push_back({cycle, o.block_n, 0, o.dir_x, o.pos_x, o.pos_y});
  if (o.step_y) pulses.push_back({cycle, o.block_n, 1, o.dir_y, o.pos_x, o.pos_y});
  was_busy_ = o.busy;
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

InterpConfig config_for_clock(double clock_hz) {
  InterpConfig cfg;
  cfg.feed_modulus = InterpConfig::feed_modulus_for(clock_hz, cfg.feed_frac_digits);
  return cfg;
}

}  // namespace ncinterp::test
