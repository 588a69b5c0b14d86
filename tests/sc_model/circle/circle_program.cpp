// Program-level support for the circle-mode tests (see the header).
#include "circle_program.h"

#include "bit_length.h"

#include <algorithm>
#include <cmath>

#include "arc_cases.h"
#include "dda_serial.h"
#include "play_monitor.h"

namespace ncinterp::test {

using circle_study::QuadrantArc;
using circle_study::random_arc;
using circle_study::run_arc;

namespace {

uint64_t magnitude(int64_t v) { return static_cast<uint64_t>(v < 0 ? -v : v); }

bool is_arc(const tape::Block& b) { return tape::is_arc(b.motion); }

QuadrantArc arc_of(const tape::Block& b) {
  QuadrantArc a;
  a.x0 = -b.i;
  a.y0 = -b.j;
  a.x1 = a.x0 + b.dx;
  a.y1 = a.y0 + b.dy;
  a.ccw = b.motion == tape::Motion::kArcCcw;
  return a;
}

}  // namespace

uint64_t block_iterations(const tape::Block& b, unsigned inc_width) {
  if (!is_arc(b)) return uint64_t{1} << bit_length(magnitude(b.dx) | magnitude(b.dy));
  return run_arc(arc_of(b), inc_width, uint64_t{1} << (inc_width + 2)).iterations;
}

tape::Program random_arc_program(std::mt19937_64& rng, int blocks, double arc_share,
                                 uint64_t modulus, unsigned inc_width) {
  const int64_t max_inc = (int64_t{1} << inc_width) - 1;
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  tape::Program p;
  for (int n = 1; n <= blocks; ++n) {
    tape::Block b;
    b.n = static_cast<uint32_t>(n);
    if (unit(rng) < arc_share) {
      const QuadrantArc a = random_arc(rng, max_inc);
      b.motion = a.ccw ? tape::Motion::kArcCcw : tape::Motion::kArcCw;
      b.i = -a.x0;
      b.j = -a.y0;
      b.dx = a.x1 - a.x0;
      b.dy = a.y1 - a.y0;
      if (magnitude(b.dx) > uint64_t(max_inc) || magnitude(b.dy) > uint64_t(max_inc)) {
        --n;
        continue;
      }
    } else {
      const double scale = std::exp(unit(rng) * std::log(double(max_inc)));
      b.dx = std::llround((unit(rng) * 2 - 1) * scale);
      b.dy = std::llround((unit(rng) * 2 - 1) * scale);
    }
    const double clocks = double(block_iterations(b, inc_width)) * (0.5 + 2.5 * unit(rng));
    b.feed = std::max<uint64_t>(1, uint64_t(double(modulus) / std::max(clocks, 1.0)));
    p.blocks.push_back(b);
  }
  return p;
}

std::vector<uint8_t> program_frames(const tape::Program& program, unsigned inc_width) {
  tape::Format f;
  f.inc_width = inc_width;
  return tape::add_parity(tape::format_program(program, f));
}

::testing::AssertionResult check_program_run(const tape::Program& program,
                                             const OutputRecorder& rec,
                                             const BlockClocks& clocks, const InterpConfig& cfg) {
  const uint64_t modulus = cfg.feed_modulus;
  const unsigned inc_width = cfg.inc_width, lead = SerialDda::player_lead_bits(cfg);
  struct Expect {
    const tape::Block* block;
    int64_t x0, y0;  // tool position at the block's start
    uint64_t count[2][2] = {{0, 0}, {0, 0}};  // [axis][plus]
  };
  std::map<uint32_t, Expect> by_n;
  int64_t x = 0, y = 0;
  for (const tape::Block& b : program.blocks) {
    if (by_n.count(b.n)) return ::testing::AssertionFailure() << "duplicate N" << b.n;
    by_n[b.n] = Expect{&b, x, y};
    x += b.dx;
    y += b.dy;
  }
  for (const OutputRecorder::Pulse& p : rec.pulses) {
    auto it = by_n.find(p.block);
    if (it == by_n.end())
      return ::testing::AssertionFailure() << "pulse at cycle " << p.cycle << " in block N"
                                           << p.block << ", not a good block of the program";
    Expect& e = it->second;
    const tape::Block& b = *e.block;
    const int64_t d = p.axis == 0 ? b.dx : b.dy;
    if (d == 0 || p.plus != (d > 0))
      return ::testing::AssertionFailure() << "block N" << b.n << ": pulse on " << "XY"[p.axis]
                                           << " at cycle " << p.cycle << " in the wrong direction";
    ++e.count[p.axis][p.plus ? 1 : 0];
    const double px = double(p.x - e.x0), py = double(p.y - e.y0);
    // The pulse against the block's path and the bound it must keep (play's monitor).
    const system::PathError pe = system::block_path_error(b, px, py);
    const double dist = pe.distance, bound = pe.bound + 1e-9;
    if (dist > bound)
      return ::testing::AssertionFailure()
             << "block N" << b.n << (is_arc(b) ? " (arc)" : " (line)") << ": pulse at cycle "
             << p.cycle << " at (" << px << ", " << py << ") from the block start is " << dist
             << " BLU off its path (bound " << bound << ")";
  }
  for (const auto& [n, e] : by_n) {
    const int64_t want[2] = {e.block->dx, e.block->dy};
    for (int a = 0; a < 2; ++a) {
      const uint64_t plus = want[a] > 0 ? uint64_t(want[a]) : 0;
      const uint64_t minus = want[a] < 0 ? uint64_t(-want[a]) : 0;
      if (e.count[a][1] != plus || e.count[a][0] != minus)
        return ::testing::AssertionFailure()
               << "block N" << n << " axis " << "XY"[a] << ": " << e.count[a][1] << " plus and "
               << e.count[a][0] << " minus pulses, programmed " << want[a];
    }
    const uint64_t iterations = block_iterations(*e.block, inc_width);
    const bool saturated = (e.block->feed * iterations << lead) >= modulus;
    const uint64_t want_clocks =
        saturated ? (iterations << lead) + 1 : (modulus + e.block->feed - 1) / e.block->feed;
    auto bc = clocks.busy.find(n);
    const uint64_t got = bc == clocks.busy.end() ? 0 : bc->second;
    if (got != want_clocks)
      return ::testing::AssertionFailure()
             << "block N" << n << (is_arc(*e.block) ? " (arc, " : " (line, ") << iterations
             << " iterations, F " << e.block->feed << "): busy " << got << " clocks, expected "
             << want_clocks << (saturated ? " (saturated)" : "");
  }
  for (const OutputRecorder::Start& s : rec.starts) {
    auto it = by_n.find(s.block);
    if (it == by_n.end()) continue;
    const tape::Block& b = *it->second.block;
    const bool saturated = (b.feed * block_iterations(b, inc_width) << lead) >= modulus;
    if (s.saturated != saturated)
      return ::testing::AssertionFailure() << "block N" << b.n << ": feed_saturated_o "
                                           << s.saturated << ", expected " << saturated;
  }
  if (rec.last.pos_x != x || rec.last.pos_y != y)
    return ::testing::AssertionFailure() << "final position (" << rec.last.pos_x << ", "
                                         << rec.last.pos_y << "), programmed (" << x << ", " << y
                                         << ")";
  return ::testing::AssertionSuccess();
}

}  // namespace ncinterp::test
