// What one register width W does to one input: the first stage's tape at W, and the
// checker's measurements of the golden model (configured at W) playing that tape.
// Idea: nothing here is computed from a formula for W. The first stage is run with
// FirstStageOptions::width = W, so the register limit splits long moves exactly as it
// would on a real tape (the paper's dy_max); the golden model plays the tape clock by
// clock and the trajectory checker measures the pulse path against the blocks (the
// interpolator's error) and the contour (the total error), and every block's time
// against 1/F. This is the `ncinterp tape` + `ncinterp check` path, in memory.
#pragma once
#include "interp_ports.h"
#include <string>
#include <vector>

#include "firststage.h"
#include "geometry/contour.h"
#include "sweep_row.h"
#include "tape/tape.h"

namespace ncinterp::sweep {

struct SweepInput {
  std::string path;
  firststage::Contour contour;
};

struct MeasureSetup {
  firststage::FirstStageOptions first_stage;  // tol, method, BLU, feed, F width; W set per call
  double clock_hz = 1e6;
  double reader_cps = 1000.0;                 // tape reader, characters per second
  unsigned pos_width = 32;                    // the golden model's position counters
  Arch arch = Arch::kSerial;                  // the golden model's microarchitecture
  bool circle_mode = true;                    // false: the lines-only core (chords only)
};

// The tape the first stage makes for the input at width W, as `ncinterp tape` writes it.
// Throws what the first stage or the tape writer throws (e.g. for a W it does not take).
struct WidthTape {
  firststage::GridPoint start;  // tape start, BLU
  tape::Program program;
  tape::Format format;
  std::vector<uint8_t> frames;  // with parity
};
WidthTape tape_at_width(const SweepInput& input, unsigned width, const MeasureSetup& setup);

// First stage, tape, golden model and checker at W. Failures (the first stage refusing W,
// a tape the reader rejects) become InputResult::failure, never an exception. With a
// tape_path the tape's frames are written there (for the RTL variant).
InputResult measure_input(const SweepInput& input, unsigned width, const MeasureSetup& setup,
                          const std::string& tape_path = "");

}  // namespace ncinterp::sweep
