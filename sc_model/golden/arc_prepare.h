// Arc preparation in the decoder: the C++ twin of rtl/arc_prepare.sv (same registers, same
// clock-by-clock outputs).
// Idea: before an arc block is handed to the block buffer, the decoder (a) checks it: zero
// radius, quadrant and register width at once from the geometry, the radius (end within
// 1 BLU of the circle) bit-serially in (5W + 4)(2W + 4) clocks (ArcRadiusCheck); and (b)
// runs the block's circle DDA once without pulses (a dry run) to learn its iteration count
// N: the decoder adds F at each iteration it marks, so the block carries S = F * N, and the
// feed generator plays its N iterations in M / F clocks, like the 2^k iterations of a line
// (docs/circle-dda.md section 4). The dry run is a CircleDda, one iteration per clock, or
// with BitSerial the bit-serial SerialDda, 2P clocks per iteration (P = W rounded up to a
// power of two). Both run in parallel with the check; a failed radius check stops the dry
// run. With BitSerial the geometry itself is found bit-serially first (rtl/arc_geometry.sv:
// W + 1 clocks from the first run edge), so everything else starts W + 1 clocks later.
#pragma once
#include <algorithm>
#include <cstdint>

#include "arc_geometry.h"
#include "arc_radius_check.h"
#include "dda_circle.h"
#include "dda_serial.h"
#include "interp_ports.h"

namespace ncinterp {

class ArcPrepare {
 public:
  ArcPrepare(unsigned inc_width, bool bit_serial);

  void reset();

  // Clocks of the geometry before the check and the dry run start: its serial pass.
  static uint64_t geometry_clocks(unsigned inc_width, bool bit_serial) {
    return bit_serial ? inc_width + 1 : 0;
  }
  // Clocks from the first run edge of a good arc of n iterations to done.
  static uint64_t clocks(unsigned inc_width, bool bit_serial, uint64_t n) {
    const uint64_t dry = bit_serial ? 2 * uint64_t{SerialDda::pass_length(inc_width)} * n : n;
    return geometry_clocks(inc_width, bit_serial) +
           std::max(dry, ArcRadiusCheck::clocks(inc_width)) + 1;
  }

  // What the decoder sees in a clock with run_i = 1: done (the result is final; the
  // decoder leaves its arc state at this edge), the error code (kNone = good arc), and
  // whether the dry run iterates at this edge (iterate_o: the decoder adds F).
  struct Result {
    bool done = false;
    TapeError error = TapeError::kNone;
    bool iterate = false;
  };

  // One clock edge with run_i = 1 and the held block's words: returns the outputs of this
  // clock (from the registers before the edge), then updates the registers.
  Result edge(const ArcWords& w);
  // One clock edge with run_i = 0.
  void idle() {
    running_ = false;
    geometry_edges_ = 0;
  }

private:
  unsigned inc_width_;
  bool serial_;             // BitSerial: serial_dry_ runs, else dry_

  bool running_ = false;    // a prepared arc is in progress (after its start edge)
  uint64_t geometry_edges_ = 0;  // run edges of the geometry's serial pass so far
  ArcGeometry g_;           // of the arc being prepared, from its start edge
  CircleDda dry_;           // the dry-run DDA (one iteration per clock)
  SerialDda serial_dry_;    // the bit-serial dry run (2P clocks per iteration)
  ArcRadiusCheck radius_;   // the bit-serial radius check ((5W + 4)(2W + 4) clocks)
};

}  // namespace ncinterp
