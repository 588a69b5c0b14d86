// Monitors of a play run (see play_monitor.h): pulse counts, positions, gaps, path error
// against the programmed chords and arcs, and block timing against the programmed 1/F.
#include "play_monitor.h"

#include "path_bounds.h"

#include <cmath>
#include <cstdlib>

namespace ncinterp::system {

double distance_to_segment(double px, double py, double dx, double dy) {
  const double len2 = dx * dx + dy * dy;
  double t = len2 > 0 ? (px * dx + py * dy) / len2 : 0.0;
  t = t < 0 ? 0 : t > 1 ? 1 : t;
  return std::hypot(px - t * dx, py - t * dy);
}

PathError block_path_error(const tape::Block& b, double px, double py) {
  if (!tape::is_arc(b.motion))
    return {distance_to_segment(px, py, static_cast<double>(b.dx), static_cast<double>(b.dy)),
            line_path_bound(b.dx, b.dy)};
  // Relative to the centre, which is at (i, j) from the block's start.
  const double i = static_cast<double>(b.i), j = static_cast<double>(b.j);
  const double r0 = std::hypot(i, j);
  const double r1 = std::hypot(static_cast<double>(b.dx) - i, static_cast<double>(b.dy) - j);
  return {std::fabs(std::hypot(px - i, py - j) - r0), arc_path_bound(r0, r1)};
}

namespace {

uint64_t block_pulses(const tape::Block& b) {
  return static_cast<uint64_t>(std::llabs(b.dx)) + static_cast<uint64_t>(std::llabs(b.dy));
}

}  // namespace

// M / F clocks, M 2^k / S for a rapid traverse (its S is the rapid step, line_step()).
double PlayMonitor::ideal_clocks(const tape::Block& b) const {
  const double m = static_cast<double>(cfg_.feed_modulus);
  if (b.motion != tape::Motion::kRapid) return b.feed ? m / static_cast<double>(b.feed) : 0.0;
  const double s = static_cast<double>(line_step(b, cfg_));
  const int k = static_cast<int>(bit_length(static_cast<uint64_t>(std::max(std::llabs(b.dx), std::llabs(b.dy)))));
  return s > 0 ? std::ldexp(m, k) / s : 0.0;
}

PlayMonitor::PlayMonitor(const tape::Program& program, const InterpConfig& cfg)
    : program_(program), cfg_(cfg) {
  for (const tape::Block& b : program_.blocks) {
    s_.expected_x += b.dx;
    s_.expected_y += b.dy;
  }
}

void PlayMonitor::observe(uint64_t cycle, const InterpOutputs& o) {
  s_.cycles = cycle;
  // Block boundaries: a load, or busy falling. (Only what the next clock needs is kept of
  // the outputs: a copy of them all stalled `play --engine rtl` by a tenth.)
  const bool load = last_.loads(o);
  const bool ends = last_.busy && (!o.busy || load);
  last_.keep(o);
  finished_ = o.done || o.error;
  if (cycle == 0) return;  // the state after reset: nothing has happened yet
  // (A timeline is empty only if an engine came out of reset busy: not a block to time.)
  if (ends && !s_.timeline.empty()) s_.timeline.back().end_cycle = cycle;
  if (load) {
    BlockTiming t;
    t.n = o.block_n;
    t.load_cycle = cycle;
    s_.timeline.push_back(t);
    started_ = true;
  }
  if (o.busy) {
    ++s_.busy_cycles;
    if (o.feed_saturated && !s_.timeline.empty()) s_.timeline.back().saturated = true;
  } else if (o.paused) {
    ++s_.paused_cycles;
  } else if (!o.done && !o.error) {
    ++(started_ ? s_.gap_cycles : s_.lead_in_cycles);
  }
  if (o.tool) ++s_.tool_on_cycles;
  if (o.step_x || o.step_y) {
    if (o.step_x) ++(o.dir_x ? s_.pulses_x.plus : s_.pulses_x.minus);
    if (o.step_y) ++(o.dir_y ? s_.pulses_y.plus : s_.pulses_y.minus);
    const uint64_t steps = (o.step_x ? 1 : 0) + (o.step_y ? 1 : 0);
    if (!s_.timeline.empty()) s_.timeline.back().pulses += steps;
    pulse(o.pos_x, o.pos_y);
    cursor_pulses_ += steps;
  }
}

void PlayMonitor::observe_quiet(uint64_t cycle, const InterpOutputs& o) {
  const uint64_t n = cycle - s_.cycles;
  s_.cycles = cycle;
  if (o.busy)
    s_.busy_cycles += n;
  else if (o.paused)
    s_.paused_cycles += n;
  else if (!o.done && !o.error)
    (started_ ? s_.gap_cycles : s_.lead_in_cycles) += n;
  if (o.tool) s_.tool_on_cycles += n;
}

void PlayMonitor::pulse(int64_t x, int64_t y) {
  const auto& blocks = program_.blocks;
  while (cursor_ < blocks.size() && cursor_pulses_ >= block_pulses(blocks[cursor_])) {
    start_x_ += blocks[cursor_].dx;
    start_y_ += blocks[cursor_].dy;
    ++cursor_;
    cursor_pulses_ = 0;
  }
  double error;
  if (cursor_ < blocks.size()) {
    const PathError e = block_path_error(blocks[cursor_], static_cast<double>(x - start_x_),
                                         static_cast<double>(y - start_y_));
    error = e.distance;
    if (error > e.bound + 1e-9) s_.path_within_bound = false;
  } else {  // a pulse the program does not have: measured from the programmed end point
    ++s_.pulses_beyond_program;
    s_.path_within_bound = false;
    error = std::hypot(static_cast<double>(x - start_x_), static_cast<double>(y - start_y_));
  }
  if (error > s_.max_path_error) {
    s_.max_path_error = error;
    s_.max_path_error_block = cursor_ < blocks.size() ? blocks[cursor_].n : last_.block_n;
  }
}

PlaySummary PlayMonitor::finish(const InterpOutputs& last) {
  s_.done = last.done;
  s_.error = last.error;
  s_.paused = last.paused;
  s_.error_code = last.error_code;
  s_.error_block = last.error_block;
  s_.error_offset = last.error_offset;
  s_.final_x = last.pos_x;
  s_.final_y = last.pos_y;
  // Idle clocks after the last block are the reader delivering the end of the tape, not a
  // gap between blocks.
  if (!s_.timeline.empty() && s_.timeline.back().end_cycle != 0 && (s_.done || s_.error)) {
    const uint64_t tail = s_.cycles - s_.timeline.back().end_cycle;
    s_.gap_cycles -= std::min(s_.gap_cycles, tail);
  }
  match_timeline();
  return s_;
}

// Matches observed blocks to tape blocks, in order. An observed block with N = n covers
// the run of consecutive tape blocks with N = n, unless the next observed block has the
// same N (a gap split the run): then it covers the fewest blocks whose pulses it emitted.
void PlayMonitor::match_timeline() {
  const auto& blocks = program_.blocks;
  size_t cur = 0;
  for (size_t i = 0; i < s_.timeline.size(); ++i) {
    BlockTiming& t = s_.timeline[i];
    if (cur >= blocks.size() || blocks[cur].n != t.n) continue;  // unmatched: block_count 0
    size_t run = 0;
    while (cur + run < blocks.size() && blocks[cur + run].n == t.n) ++run;
    size_t take = run;
    if (i + 1 < s_.timeline.size() && s_.timeline[i + 1].n == t.n) {
      uint64_t sum = 0;
      take = 1;
      for (size_t j = 1; j <= run; ++j) {
        sum += block_pulses(blocks[cur + j - 1]);
        if (sum == t.pulses) {
          take = j;
          break;
        }
      }
    }
    t.first_block = cur;
    t.block_count = take;
    for (size_t j = 0; j < take; ++j) t.ideal_cycles += ideal_clocks(blocks[cur + j]);
    cur += take;
  }
  // A run cut off by the end of the simulation does not count as played.
  if (!s_.timeline.empty() && s_.timeline.back().end_cycle == 0 && s_.timeline.back().block_count)
    cur -= s_.timeline.back().block_count;
  s_.blocks_played = cur;

  for (const BlockTiming& t : s_.timeline) {
    if (t.block_count == 0 || t.end_cycle == 0) continue;
    if (t.saturated) {
      ++s_.saturated_blocks;
      continue;
    }
    ++s_.timed_blocks;
    const double err = static_cast<double>(t.cycles()) - t.ideal_cycles;
    const double rel = err / t.ideal_cycles;
    if (std::fabs(rel) > std::fabs(s_.worst_relative_time_error) || s_.timed_blocks == 1) {
      s_.worst_relative_time_error = rel;
      s_.worst_time_error_cycles = err;
      s_.worst_time_error_block = t.n;
    }
  }
}

}  // namespace ncinterp::system
