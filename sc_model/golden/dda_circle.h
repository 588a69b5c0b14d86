// Circle DDA of one quadrant arc, which also plays a line: the C++ twin of rtl/dda_circle.sv
// (the same values every
// clock; the RTL keeps the two axes by role, A = first in the next iteration, and swaps
// them after each iteration, this model keeps them by name with y_first_ = a_is_y_q; the
// one-clock step registers are the caller's outputs, as in GoldenInterp).
// Idea (docs/circle-dda.md): two cross-coupled integrators with modulus 2^k. The X
// integrator adds |y| and the Y integrator adds |x| (coordinates relative to the centre);
// a carry is a step of that axis, which moves its own magnitude by one BLU, so the other
// integrator sees the new value. Update is immediate (semi-implicit): within one iteration
// the second half-step already uses the coordinate the first one just moved, and the order
// alternates every iteration (X first, then Y first, ...). This integer map is invertible,
// so its orbit closes instead of spiralling out (forward Euler), and the alternation
// cancels the first-order tilt of the closed curve: the pulse path stays within 0.88 BLU of
// the circle (measured, bench/circle). Per-axis pulse counters stop each axis exactly at
// the programmed end; an axis whose partner has finished integrates at least 2^(k-1) per
// iteration, so its last pulses come out even where the other coordinate is 0.
// A line (load_line) runs on the same integrators with constant integrands: each adds its
// own axis's |d| for exactly 2^k iterations (method L1), so a magnitude register holds the
// other axis's |d| and never moves, and the block ends after the 2^k-th iteration.
#pragma once
#include <cstdint>

#include "arc_geometry.h"

namespace ncinterp {

// The circle DDA's measured path bound (docs/circle-dda.md 3.2, bench/circle), BLU: every
// pulse position of a good arc is within kCircleDdaBound + |R1 - R0| of the circle through
// the block's start about its centre (R0, R1: start and end radius); path_bounds.h.
constexpr double kCircleDdaBound = 0.88;

class CircleDda {
 public:
  struct Steps {
    bool x = false, y = false;
  };

  // Registers after a load edge of an arc.
  void load(const ArcGeometry& g, bool dir_x, bool dir_y) {
    line_ = false;
    kpow_ = uint64_t{1} << g.k;
    rem_ = kpow_;
    acc_[0] = acc_[1] = kpow_ >> 1;
    mag_[0] = g.x0;
    mag_[1] = g.y0;
    cnt_[0] = g.cnt_x;
    cnt_[1] = g.cnt_y;
    grow_[0] = g.grow_x;
    grow_[1] = g.grow_y;
    dir_[0] = dir_x;
    dir_[1] = dir_y;
    y_first_ = false;
  }

  // Registers after a load edge of a line of |dx|, |dy| with k = bit length of
  // max(|dx|, |dy|) (the decoder's k): the magnitude registers hold the other axis's |d|.
  void load_line(unsigned k, uint32_t dx, uint32_t dy, bool dir_x, bool dir_y) {
    line_ = true;
    kpow_ = uint64_t{1} << k;
    rem_ = kpow_;
    acc_[0] = acc_[1] = kpow_ >> 1;
    mag_[0] = dy;
    mag_[1] = dx;
    cnt_[0] = dx;
    cnt_[1] = dy;
    grow_[0] = grow_[1] = false;
    dir_[0] = dir_x;
    dir_[1] = dir_y;
    y_first_ = false;
  }

  // One iteration (an edge with the iteration strobe while !done()); the steps it emits.
  Steps iterate() {
    bool step[2];
    if (line_) {
      // A line's half-steps are independent: the order does not matter. (The RTL's rem_q
      // counts for an arc too; nothing reads it there.)
      --rem_;
      step[0] = line_half_step(0);
      step[1] = line_half_step(1);
    } else {
      const int first = y_first_ ? 1 : 0;
      const int second = 1 - first;
      step[first] = half_step(first);
      step[second] = half_step(second);  // sees the first axis's new magnitude and count
    }
    y_first_ = !y_first_;
    return Steps{step[0], step[1]};
  }

  // The block's iterations are over: a line's 2^k, an arc's when both axes have emitted all
  // their pulses.
  bool done() const { return line_ ? rem_ == 0 : cnt_[0] == 0 && cnt_[1] == 0; }
  bool dir(int axis) const { return dir_[axis]; }
  // The iterations until done(), by a dry run on a copy (an arc's N: no closed form).
  uint64_t iterations_left() const {
    CircleDda dry = *this;
    uint64_t n = 0;
    for (; !dry.done(); ++n) dry.iterate();
    return n;
  }

  // Register access for tests, the bench and the golden model's fault hook.
  uint64_t kpow() const { return kpow_; }
  uint64_t acc(int axis) const { return acc_[axis]; }
  uint64_t mag(int axis) const { return mag_[axis]; }
  uint32_t count(int axis) const { return cnt_[axis]; }
  bool y_first() const { return y_first_; }
  void add_to_integrator(int axis, uint64_t v) { acc_[axis] += v; }

 private:
  // A line's half-step (rtl/dda_circle.sv with line_q): the other axis's magnitude
  // register holds this axis's |d| and never moves, the counter only counts, and there is
  // no finishing rule.
  bool line_half_step(int a) {
    const uint64_t sum = acc_[a] + mag_[1 - a];
    acc_[a] = sum & ~kpow_;
    const bool step = (sum & kpow_) != 0 && cnt_[a] != 0;
    cnt_[a] -= step;
    return step;
  }

  // An arc's half-step: axis a integrates the other axis's magnitude; a carry out of bit k
  // is a step, which moves this axis's magnitude by one BLU. Once the other axis has no
  // pulses left, the addend is at least half the modulus (magnitude OR 2^(k-1): the
  // finishing rule).
  bool half_step(int a) {
    const int b = 1 - a;
    const uint64_t addend = cnt_[b] == 0 ? (mag_[b] | (kpow_ >> 1)) : mag_[b];
    const uint64_t sum = acc_[a] + addend;  // < 2^(k+1)
    acc_[a] = sum & ~kpow_;
    const bool step = (sum & kpow_) != 0 && cnt_[a] != 0;
    if (step) {
      --cnt_[a];
      mag_[a] = grow_[a] ? mag_[a] + 1 : mag_[a] - 1;
    }
    return step;
  }

  // 64 bits: k goes up to W = 32, so 2^k and acc + addend need W + 1 bits.
  uint64_t kpow_ = 0;           // 2^k, one-hot
  uint64_t acc_[2] = {0, 0};    // integrators, in [0, 2^k)
  uint64_t mag_[2] = {0, 0};    // |x|, |y| relative to the centre
  uint32_t cnt_[2] = {0, 0};    // pulses left per axis
  bool grow_[2] = {false, false};
  bool dir_[2] = {false, false};  // 1 = plus, held for the block
  bool y_first_ = false;        // this iteration steps Y before X
  bool line_ = false;           // a line: constant magnitudes, 2^k iterations
  uint64_t rem_ = 0;            // a line's iterations left
};

}  // namespace ncinterp
