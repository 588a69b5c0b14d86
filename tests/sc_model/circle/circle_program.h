// Program-level support for the circle-mode tests of the whole interpolator (golden model
// and lock-step cosim): random programs of quadrant arcs and lines, their tape frames, and
// the checks every run must pass, derived from the programmed blocks only.
#pragma once
#include <gtest/gtest.h>

#include <cstdint>
#include <map>
#include <random>
#include <vector>

#include "dda_circle.h"
#include "interp_ports.h"
#include "interp_test_support.h"
#include "tape.h"

namespace ncinterp::test {

// A random program: `blocks` motion blocks, about arc_share of them quadrant arcs (radius
// log-uniform 1 .. 2^W - 1, random quadrant, direction, full or partial) and the rest
// lines. F is chosen per block so that it takes 0.5 to 3 times its iteration count in
// clocks at this feed modulus: about a third of the blocks saturate, and runs stay short.
tape::Program random_arc_program(std::mt19937_64& rng, int blocks, double arc_share,
                                 uint64_t modulus, unsigned inc_width = 16);

// Tape frames (ISO 840 parity) of a program, written by the tape writer.
std::vector<uint8_t> program_frames(const tape::Program& program, unsigned inc_width = 16);

// The block's DDA iteration count: 2^k for a line, the circle DDA's N for an arc.
uint64_t block_iterations(const tape::Block& b, unsigned inc_width = 16);

// Busy clocks per block N (block numbers must be unique).
struct BlockClocks {
  void observe(const InterpOutputs& o) {
    if (o.busy) ++busy[o.block_n];
  }
  std::map<uint32_t, uint64_t> busy;
};

// Checks a run that played `program` completely (or the blocks before a bad one):
// - every pulse comes while block_n shows a good block, in its direction;
// - per block and axis, the pulse count equals the increment; the final position is the
//   sum of the increments;
// - every pulse position is within the bound of its block: the L1 bound of the chord for a
//   line (docs/interpolator.md 5.6), the circle bounds above for an arc;
// - each block is busy for ceil(M / F) clocks, or when saturated (S << lead >= M, the
//   DDA's clocks per iteration are 2^lead: 1 parallel, 2P serial) its iterations' clocks
//   + 1, and feed_saturated_o shows which.
// The machine is cfg's (its arch, width and feed modulus).
::testing::AssertionResult check_program_run(const tape::Program& program,
                                             const OutputRecorder& rec,
                                             const BlockClocks& clocks, const InterpConfig& cfg);

}  // namespace ncinterp::test
