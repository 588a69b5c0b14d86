// The feed plan of a tape: how long the machine takes to play it with the feed ramp, by
// block, at exact stop (what the interpolator plays, docs/motion-control.md) and, planned
// only, in continuous mode with the junction-deviation rule of grbl and Klipper and a
// given look-ahead (what G64 would buy: it is not built).
// Idea: the interpolator ramps its iteration rate u, not a speed: from rest at du per
// clock to the block's rate S (capped), and back to rest, over its N iterations. In
// iteration space every block is a trapezoid (or a triangle) with the same acceleration
// du / M, so its time at exact stop is exact up to a few clocks of quantisation
// (GoldenRamp.EachBlockLastsItsIdealTrapezoidWithinAFewClocks) whatever its shape. The
// same ramp moves the path by L / N mm per iteration, so block i accelerates along its
// path at a_i = (du / M) f^2 L_i / N_i; continuous mode is planned with these a_i, the
// junction speeds of the corners' angles, the blocks' rates (arcs also below sqrt(A R))
// and a machine that can always stop within the blocks it has read: a backward pass over
// the look-ahead window from rest, a forward pass from rest at the start.
#pragma once
#include <cstddef>
#include <vector>

#include "interp_ports.h"
#include "tape.h"

namespace ncinterp::checker {

struct FeedPlanOptions {
  double accel_mm_s2 = 500;            // the machine's limit (InterpConfig::accel_step_for)
  double junction_deviation_mm = 0.01;  // continuous mode's corner rule
  // Continuous mode's look-ahead: the blocks read beyond the one playing (1: the block
  // buffer's next block); 0 is the whole program (the first stage's view).
  std::vector<unsigned> lookaheads = {1, 2, 4, 0};
};

struct ContinuousPlan {
  unsigned lookahead = 0;  // 0: the whole program
  double seconds = 0;
};

struct FeedPlan {
  size_t blocks = 0;
  double programmed_s = 0;  // no ramp: every block at its rate from its first clock
  double exact_stop_s = 0;  // every block ramped from rest to rest (the machine with --accel)
  std::vector<ContinuousPlan> continuous;  // per look-ahead of the options, in their order
};

// The plan of `program` on the interpolator `cfg` (its clock's M, the rapid step and the
// rate cap; cfg.accel_step is replaced by the step of o.accel_mm_s2) at clock_hz.
// Throws std::invalid_argument for a limit below one ramp step.
FeedPlan plan_feed(const tape::Program& program, const InterpConfig& cfg, double clock_hz,
                   const FeedPlanOptions& o);

// A block's DDA iterations N: 2^k for a line or a rapid (k = bit length of max(|dx|,
// |dy|)), an arc's dry-run count (its circle DDA run until both axes are done); 1 for a
// still block.
uint64_t block_iterations(const tape::Block& b, const InterpConfig& cfg);

}  // namespace ncinterp::checker
