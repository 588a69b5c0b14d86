// Bit-serial DDA, clock by clock: the C++ twin of rtl/dda_serial.sv (the player's DDA and
// the arc's dry run with BitSerial).
// Idea: the RTL computes an iteration bit by bit in two passes of P = 2^ceil(log2 W) clocks,
// but what it shows outside (when an iteration starts, its pulses, when the block's words
// have been read, when the block is done) depends only on the iteration's result and on
// the schedule. So this model computes the iteration at once with CircleDda, the same
// integers as dda_circle.sv, and plays its outputs at the RTL's clocks; the lock step
// compares the two every clock, which checks the RTL's bit-level arithmetic against an
// independent model. The schedule (docs/interpolator.md 5.6): an iteration starts at an
// edge with a strobe while idle and not done (clock 0 of its first pass); its pulses come
// together at clock k - 1 (a line) or P + k - 1 (an arc, whose second axis is known only in
// the second pass); the block's words are read until clock P - 1; the iteration ends at
// clock 2P - 1, done if it was the block's last.
#pragma once
#include <cstdint>

#include "arc_geometry.h"
#include "dda_circle.h"
#include "interp_ports.h"

namespace ncinterp {

class SerialDda {
 public:
  explicit SerialDda(unsigned inc_width) : pass_(pass_length(inc_width)) {}

  // P: the pass length, W rounded up to a power of two (the RTL's bit counter wraps).
  static unsigned pass_length(unsigned inc_width) {
    unsigned p = 1;
    while (p < inc_width) p <<= 1;
    return p;
  }
  // An iteration's clocks, 2P, and their log2: the feed generator's lead
  // (feed_generator.sv's LeadBits).
  static unsigned iteration_clocks(unsigned inc_width) { return 2 * pass_length(inc_width); }
  // The clocks after a stop (E-stop, a limit) that a run is watched on for a pulse an
  // unmuted iteration in flight would still emit: two iterations, in both archs.
  static unsigned stop_watch_clocks(unsigned inc_width) { return 2 * iteration_clocks(inc_width); }
  static unsigned lead_bits(unsigned inc_width) {
    unsigned bits = 1;  // 2P = 2^bits
    while ((1u << bits) < 2 * inc_width) ++bits;
    return bits;
  }
  // The player's DDA's lead: SerialDda's with BitSerial, 0 for CircleDda (one clock).
  static unsigned player_lead_bits(const InterpConfig& cfg) {
    return cfg.serial() ? lead_bits(cfg.inc_width) : 0;
  }

  // A load edge of an arc / a line (as CircleDda::load, load_line).
  void load(const ArcGeometry& g, bool dir_x, bool dir_y) {
    dda_.load(g, dir_x, dir_y);
    begin(g.k, false);
  }
  void load_line(unsigned k, uint32_t dx, uint32_t dy, bool dir_x, bool dir_y) {
    dda_.load_line(k, dx, dy, dir_x, dir_y);
    begin(k, true);
  }

  struct Edge {
    bool iterate = false;  // an iteration starts at this edge (iterate_o)
    bool x = false, y = false;  // pulses at this edge (carry_x_o, carry_y_o)
  };
  // One edge that is not a load edge, with strobe_i.
  Edge edge(bool strobe) {
    Edge e;
    if (!run_) {
      if (!strobe || done_) return e;
      e.iterate = true;
      run_ = true;
      clock_ = 0;
      steps_ = dda_.iterate();
    } else {
      ++clock_;
    }
    if (k_ != 0 && clock_ + 1 == (line_ ? 0 : pass_) + k_) {
      e.x = steps_.x;
      e.y = steps_.y;
    }
    if (clock_ + 1 == pass_) words_ = false;
    if (clock_ + 1 == 2 * pass_) {
      run_ = false;
      done_ = dda_.done();
    }
    return e;
  }

  // Event jumping (GoldenInterp::quiet_ticks): while an iteration runs, the edges from now
  // on at which it shows nothing outside, up to its next pulse, words or end edge (the edge
  // that takes clock_ to T - 1 is target T's event); skip(n) passes n of them.
  uint64_t quiet_edges() const {
    if (!run_) return 0;
    unsigned next = 2 * pass_;
    const auto sooner = [&](unsigned target) {
      if (target >= clock_ + 2 && target < next) next = target;
    };
    if (k_ != 0) sooner((line_ ? 0 : pass_) + k_);
    if (words_) sooner(pass_);
    return next - clock_ - 2;
  }
  void skip(uint64_t n) { clock_ += static_cast<unsigned>(n); }

  bool done() const { return done_; }    // done_o
  bool running() const { return run_; }  // an iteration's passes run
  bool words() const { return words_; }  // words_o: the block's words are still read
  bool dir(int axis) const { return dda_.dir(axis); }
  // The iteration's values (tests, the fault hook).
  CircleDda& dda() { return dda_; }

 private:
  void begin(unsigned k, bool line) {
    k_ = k;
    line_ = line;
    run_ = false;
    words_ = true;
    done_ = false;  // every block has at least one iteration (a good arc moves)
  }

  CircleDda dda_;
  unsigned pass_;
  unsigned k_ = 0;
  bool line_ = false;
  bool run_ = false, words_ = false, done_ = true;  // done after reset, as the RTL
  unsigned clock_ = 0;      // of the running iteration, 0 at its start edge
  CircleDda::Steps steps_;  // its pulses
};

}  // namespace ncinterp
