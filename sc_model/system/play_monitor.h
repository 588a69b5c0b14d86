// Monitors of a play run: what the interpolator's outputs show, clock by clock, judged
// against the program read back from the tape.
// Idea: the monitor sees only the interpolator's ports (the same for the golden model and
// the RTL), once per clock after the edge, and the programmed blocks (tape::Program from
// the software reader). From these it measures
//   - pulses per axis and direction, final position, gap clocks;
//   - path error: every pulse position's distance to its block's programmed chord, or for
//     an arc to the circle through its start. Pulses are assigned to blocks by count
//     (block k owns the |dx_k| + |dy_k| pulses after those of blocks 0..k-1), which needs
//     no block boundary on the ports;
//   - block timing: a block starts where busy rises or block_n changes while busy and
//     ends at the next start or where busy falls; its clocks are compared with the
//     programmed 1/F minute (docs/interpolator.md section 5.4).
// Plain C++ (no SystemC) so it is unit-tested on its own and reusable by other runners.
#pragma once
#include <cstdint>
#include <optional>
#include <vector>

#include "dda_circle.h"
#include "interp_ports.h"
#include "tape.h"

namespace ncinterp::system {

struct AxisPulses {
  uint64_t plus = 0, minus = 0;
};

// One observed block: from its load edge to the edge where the next block loads or busy
// falls. Consecutive tape blocks with the same N and no gap between them cannot be told
// apart on the ports and form one observed block (its ideal time is their sum).
struct BlockTiming {
  uint32_t n = 0;
  uint64_t load_cycle = 0;
  uint64_t end_cycle = 0;          // 0 while playing
  uint64_t pulses = 0;
  bool saturated = false;          // feed_saturated_o seen during the block
  size_t first_block = 0;          // index into Program::blocks
  size_t block_count = 0;          // tape blocks it covers (0 = could not be matched)
  double ideal_cycles = 0;         // programmed duration: 60 f_clk / F per block, summed
  uint64_t cycles() const { return end_cycle - load_cycle; }
};

struct PlaySummary {
  uint64_t cycles = 0;  // last cycle observed (the one done/error rose in, if it did)
  bool done = false, error = false;
  bool paused = false;  // the run ended paused (M00, M01) with no cycle start to come
  uint8_t error_code = 0;
  uint32_t error_block = 0, error_offset = 0;
  AxisPulses pulses_x, pulses_y;
  int64_t final_x = 0, final_y = 0;
  int64_t expected_x = 0, expected_y = 0;  // sum of the programmed blocks
  uint64_t lead_in_cycles = 0;  // before the first block loads (reading the first block)
  uint64_t gap_cycles = 0;      // idle between blocks: the reader was too slow
  uint64_t busy_cycles = 0;
  uint64_t paused_cycles = 0;   // waiting for cycle start after an M00 (or M01)
  uint64_t tool_on_cycles = 0;  // the tool output on (M03 to M05)
  // Path error (BLU): the largest distance of a pulse position from its block's path.
  double max_path_error = 0;
  uint32_t max_path_error_block = 0;
  bool path_within_bound = true;    // every pulse within its own block's bound (below)
  uint64_t pulses_beyond_program = 0;  // more pulses than the program has
  size_t blocks_played = 0;          // tape blocks covered by observed blocks
  std::vector<BlockTiming> timeline;
  // Feed accuracy over blocks that are not saturated and were matched to the tape.
  size_t timed_blocks = 0, saturated_blocks = 0;
  double worst_relative_time_error = 0;  // (measured - ideal) / ideal
  double worst_time_error_cycles = 0;    // measured - ideal, clocks
  uint32_t worst_time_error_block = 0;
};

class PlayMonitor {
 public:
  // `feed_modulus` is M = 60 f_clk 10^FeedFracDigits; ideal block clocks are M / F.
  // The machine cfg gives the programmed block times (its feed modulus, and its rapid step
  // for G00 blocks).
  PlayMonitor(const tape::Program& program, const InterpConfig& cfg);

  // The outputs after edge `cycle` (0 = after reset). Call once per clock, in order.
  void observe(uint64_t cycle, const InterpOutputs& o);
  // The clocks after the last observed one up to `cycle` showed o, the outputs last
  // observed, with no step (event jumping, system_top.h): what observe() does for each.
  void observe_quiet(uint64_t cycle, const InterpOutputs& o);
  // Closes the last block and matches the observed blocks to the tape's blocks; `last` is
  // the outputs last observed (their final state, error and position go in the summary).
  PlaySummary finish(const InterpOutputs& last);

  bool finished() const { return finished_; }
  // Progress: tape blocks whose pulses are complete.
  size_t pulse_block() const { return cursor_; }

 private:
  void pulse(int64_t x, int64_t y);
  void match_timeline();
  double ideal_clocks(const tape::Block& b) const;

  const tape::Program& program_;
  InterpConfig cfg_;
  PlaySummary s_;
  BlockLoadWatch last_;    // the outputs last observed
  bool finished_ = false;  // done or error
  bool started_ = false;  // a block has loaded
  // Pulse-to-block assignment.
  size_t cursor_ = 0;
  uint64_t cursor_pulses_ = 0;
  int64_t start_x_ = 0, start_y_ = 0;  // programmed start of block cursor_
};

// Distance from point (px, py) to the segment (0,0)-(dx,dy).
double distance_to_segment(double px, double py, double dx, double dy);

// A pulse position (px, py), relative to the block's start, against the block's path: the
// distance to the chord (line) or to the circle through the start (arc), and the bound that
// distance must keep (path_bounds.h).
struct PathError {
  double distance, bound;
};
PathError block_path_error(const tape::Block& b, double px, double py);

}  // namespace ncinterp::system
