// Test support shared by the golden-model and cosim tests: line tapes, a recorder of the
// interpolator's outputs and the checks every run must pass.
// Idea: the checks are derived from the programmed blocks (the math of the tape), never
// from either engine: pulses per axis and direction equal the increments, every pulse
// happens while block_n shows its block, and every pulse position is within the L1 bound
// (|dx|+|dy|) / (2 sqrt(dx^2+dy^2)) of the block's chord.
#pragma once
#include <gtest/gtest.h>

#include <cstdint>
#include <ostream>
#include <random>
#include <string>
#include <string_view>
#include <vector>

#include "frame_source.h"
#include "interp_top.h"
#include "interp_ports.h"

namespace ncinterp::test {

// One motion block of a line tape; dx, dy in BLU, feed in 10^-feed_frac_digits 1/min.
struct LineBlock {
  uint32_t n = 0;
  int64_t dx = 0, dy = 0;
  uint64_t feed = 0;
};

// Tape text of the line blocks (ncinterp::tape::format_program: "%", setup block, the
// blocks, M02, "%").
std::string line_tape_text(const std::vector<LineBlock>& blocks, unsigned frac_digits = 3,
                           unsigned feed_frac_digits = 3);
// Frames of a tape text with ISO 840 even parity in bit 7 (ncinterp::tape::add_parity).
std::vector<uint8_t> frames_of(std::string_view text);

// Records what the interpolator's outputs show, cycle by cycle.
class OutputRecorder {
 public:
  struct Pulse {
    uint64_t cycle;
    uint32_t block;
    int axis;  // 0 = X, 1 = Y
    bool plus;
    int64_t x, y;  // position after the clock
  };
  struct Start {
    uint64_t cycle;
    uint32_t block;
    bool saturated;
  };
  void observe(uint64_t cycle, const InterpOutputs& o);

  std::vector<Pulse> pulses;
  std::vector<Start> starts;  // busy rising, or block_n changing while busy
  uint64_t busy_cycles = 0;
  uint64_t cycles = 0;
  InterpOutputs last;

 private:
  BlockLoadWatch load_;
};

// Checks a run of a line program that played completely (or up to an error: pass the
// blocks before the bad one). Block numbers must be unique.
::testing::AssertionResult check_line_program(const std::vector<LineBlock>& blocks,
                                              const OutputRecorder& rec);

// Runs the golden model on frames until done, error or max_cycles; records every clock.
InterpOutputs run_golden(GoldenInterp& dut, const std::vector<uint8_t>& frames,
                         uint64_t cycles_per_frame, uint64_t max_cycles, OutputRecorder& rec);

// A random line program: 1..8 blocks; increments are 0, +-(2^inc_width - 1), uniform over
// the whole range, medium or small, of both signs; feeds make each block last
// 1 .. 3 * 2^k + 8 clocks (a mix of saturated and phase-accumulated blocks that keeps the
// runs short).
std::vector<LineBlock> random_line_program(std::mt19937_64& rng, unsigned inc_width,
                                           uint64_t modulus);

// A bad tape (for the default widths): the error it must raise and the good blocks before
// it, which must play completely. Used on both engines.
struct BadTape {
  const char* name;
  std::string text;
  TapeError code;
  uint32_t block;
  size_t offset;
  std::vector<LineBlock> good;
  // The frames; the parity case flips bit 7 of the frame at `offset`.
  std::vector<uint8_t> frames() const;
};
void PrintTo(const BadTape& t, std::ostream* os);
std::vector<BadTape> bad_tapes();

}  // namespace ncinterp::test
