// Dry run of an arc's circle DDA, clock by clock: the C++ twin of rtl/arc_dry_run.sv (same
// registers, same schedule). What it counts is CircleDda's iterations of the same arc.
// Idea: bit-serial arithmetic, one half-step per pass of W clocks. Six circulating
// registers (acc, mag, cnt per axis), LSB first; pass p integrates axis X, Y, Y, X, ... (p
// mod 4) and applies the previous pass's step to that pass's axis on the way, so the
// second half-step of an iteration sees the moved magnitude. At clock k - 1 of a pass the
// step is known; an even pass checks there whether both counts are 0 (done) or counts an
// iteration. Iteration j is marked 2jW + k edges after the start edge; done after
// 2NW + k.
#pragma once
#include <cstdint>

#include "arc_geometry.h"

namespace ncinterp {

class ArcDryRun {
 public:
  explicit ArcDryRun(unsigned inc_width) : w_(inc_width) {}

  // Edges from the start edge until done() for an arc of n iterations (bit length k).
  static uint64_t clocks(unsigned inc_width, uint64_t iterations, unsigned k) {
    return 2 * uint64_t{inc_width} * iterations + k;
  }

  // The start edge (start_i) of arc g.
  void start(const ArcGeometry& g);
  bool done() const { return done_; }
  // One edge of the running dry run (run_i, !done()); returns iterate_o of this clock.
  bool step(const ArcGeometry& g);

 private:
  unsigned w_;
  // acc_, mag_, cnt_: [0] = X, [1] = Y, W bits, circulating (bit i at bit 0 at clock i).
  uint64_t acc_[2] = {0, 0}, mag_[2] = {0, 0}, cnt_[2] = {0, 0};
  unsigned half_ = 0;  // p mod 4
  unsigned bit_ = 0;   // i
  bool pend_ = false, step_ = false;  // the previous pass's step, this pass's
  bool carry_acc_ = false, carry_mag_ = false, carry_cnt_ = false;
  bool zero_[2] = {false, false};     // no pulses left (U: before this pass's update)
  bool zrun_ = false;                 // U's updated count is 0 in the bits so far
  bool busy_ = false, done_ = false;
};

}  // namespace ncinterp
