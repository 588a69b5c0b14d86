// Test support for the checker tests: tapes from programs, random line programs, and a
// clean or faulty golden run recorded clock by clock.
#pragma once
#include <cstdint>
#include <random>
#include <vector>

#include "check_session.h"
#include "tape/tape.h"

namespace ncinterp::checker::test {

// Frames (with parity) of a program, format defaults (BLU 0.001, W 16).
std::vector<uint8_t> frames_of(const tape::Program& program, const tape::Format& format = {});

// A random line program: `blocks` blocks with increments of random bit length (0..max_bits),
// feeds giving block times between min_clocks and max_clocks at `modulus` (some saturate).
tape::Program random_line_program(std::mt19937& rng, int blocks, unsigned max_bits,
                                  uint64_t modulus, uint64_t min_clocks, uint64_t max_clocks);

// Every output of the golden model after every clock (index = cycle), with the operator's
// `events`.
std::vector<InterpOutputs> golden_trace(const std::vector<uint8_t>& frames, const InterpConfig& cfg,
                                        uint64_t cycles_per_frame,
                                        const GoldenInterp::Fault* fault = nullptr,
                                        const std::vector<OperatorEvent>& events = {});

}  // namespace ncinterp::checker::test
