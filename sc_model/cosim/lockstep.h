// Lock-step cosimulation: the verilated RTL and the golden model play the same tape, each
// fed by its own FrameSource, and every output is compared after every clock.
// Idea: both engines are cycle models with identical ports and timing, so the first clock
// where any output differs is a bug in one of them (or an injected fault); the report names
// the cycle, the block N playing, the signal, expected (golden) and actual (RTL) values and
// how many clocks matched before. Also collects the run's pulse and block statistics.
#pragma once
#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "interp_top.h"
#include "interp_ports.h"
#include "operator_events.h"

namespace ncinterp::cosim {

struct Options {
  InterpConfig config;                 // default widths (the RTL's), arch + feed_modulus
  uint64_t cycles_per_frame = 1000;    // reader speed (FrameSource::cycles_per_frame_for)
  uint64_t max_cycles = 1'000'000'000;  // a run that does not end by then is stopped
  GoldenInterp::Fault fault;           // test hook: a fault injected into the golden model
  std::vector<OperatorEvent> events;   // the operator's presses (--events)
  // Called every 2^24 clocks with the cycle number (e.g. progress on a terminal).
  std::function<void(uint64_t cycle)> progress;
};

struct Mismatch {
  uint64_t cycle = 0;           // first clock whose outputs differ (1 = first after reset)
  uint32_t block = 0;           // block_n of the golden model at that clock
  std::string signal;           // RTL port name, e.g. "step_x_o"
  int64_t expected = 0;         // golden model
  int64_t actual = 0;           // RTL
  uint64_t cycles_matched = 0;  // clocks before it whose outputs all matched
};

// Statistics of a run, from the (equal) outputs and the golden model's block counter.
struct Stats {
  uint64_t blocks = 0;            // motion blocks loaded
  uint64_t saturated_blocks = 0;  // of which feed_saturated
  uint64_t pulses[2][2] = {{0, 0}, {0, 0}};  // [axis 0 = X, 1 = Y][0 = minus, 1 = plus]
  uint64_t gap_cycles = 0;        // clocks with no block playing between two blocks
};

struct Result {
  // kPaused: at an M00 (or M01 with the optional stop on) that no cycle start press resumes.
  enum class End { kDone, kTapeError, kMismatch, kCycleLimit, kPaused };
  End end = End::kCycleLimit;
  uint64_t cycles = 0;              // clocks simulated
  std::optional<Mismatch> mismatch;
  InterpOutputs last;               // golden outputs after the last clock
  Stats stats;
};

using Observer = std::function<void(uint64_t cycle, const InterpOutputs& golden)>;

// Runs to done, tape error, first mismatch or the cycle limit. observer (optional) sees
// the golden outputs after reset (cycle 0) and after every clock.
Result run_lockstep(const std::vector<uint8_t>& frames, const Options& options,
                    const Observer& observer = nullptr);

// The first output that differs, in port order (expected = golden, actual = RTL); its
// cycle, block and cycles_matched are left for the caller.
Mismatch first_difference(const InterpOutputs& golden, const InterpOutputs& rtl);

// One line: "cycle C, block N, signal S: expected E, actual A (K cycles matched)".
std::string describe(const Mismatch& m);

}  // namespace ncinterp::cosim
