// One row of the bit-width sweep: everything measured at one register width W.
// Idea: a value is either measured or absent with the reason it is absent (a tool not on
// PATH, a failed run, a design too big for the part, a stage not asked for). Nothing is
// ever estimated to fill a gap, so the table says exactly what was measured; totals over
// the inputs exist only when every input was measured.
#pragma once
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace ncinterp::sweep {

struct Measured {
  std::optional<double> value;
  std::string reason;  // why there is no value

  static Measured of(double v) { return Measured{v, ""}; }
  static Measured absent(std::string why) { return Measured{std::nullopt, std::move(why)}; }
  bool ok() const { return value.has_value(); }
};

// One input (contour file) played at W: its tape from the first stage and the checker's
// measurements of the golden model playing it.
struct InputResult {
  std::string input;            // file name as given
  std::string failure;          // why nothing was measured (first stage refused W, ...)
  uint64_t blocks = 0;          // tape blocks (motion blocks)
  uint64_t frames = 0;          // tape length in characters (8-bit frames)
  double path_error_max_blu = 0.0;   // interpolator error: pulse path to programmed blocks
  double total_error_max_mm = 0.0;   // total error: pulse path to the contour
  uint64_t violations = 0;           // checker rules failed (incl. the tolerance)
  std::string first_violation;
  double feed_error_worst = 0.0;     // worst block time against 1/F, relative
  uint64_t saturated_blocks = 0;
  uint64_t cycles = 0;               // clocks simulated to the end of the program
  std::string tape_path;             // the tape, written for the RTL variant
  bool measured() const { return failure.empty(); }
};

// Hardware cost of the RTL at W (yosys, nextpnr-ice40).
struct SynthResult {
  Measured cells;             // yosys `synth`: generic cells
  Measured flip_flops;        // of which flip-flops
  Measured ice40_luts;        // yosys `synth_ice40`: SB_LUT4
  Measured ice40_logic_cells; // nextpnr-ice40, HX8K: logic cells of the placed harness
  Measured fmax_mhz;          // nextpnr-ice40, HX8K: after routing
  Measured small_logic_cells; // nextpnr-ice40 on the small part (HX1K): logic cells
  Measured small_fmax_mhz;    // and Fmax there
  bool from_cache = false;
};

// The RTL variant at W in lock step with the golden model at W, on every input's tape.
struct RtlResult {
  bool ran = false;
  bool all_match = false;  // every tape ran to its end with equal outputs on every clock
  std::string summary;     // "match (N tapes)", the first mismatch, or why it did not run
};

struct SweepRow {
  unsigned width = 0;
  std::vector<InputResult> inputs;  // in the order of the sweep's inputs
  SynthResult synth;
  RtlResult rtl;

  // Aggregates over the inputs exist only when every input was measured at this width (a
  // total over some of them would read as a total over all); else nullopt.
  std::optional<uint64_t> total(uint64_t InputResult::*field) const;
  std::optional<double> worst(double InputResult::*field) const;  // largest magnitude, signed
  // "<file name>: <why>" of the first input not measured; "" when all were.
  std::string missing_input() const;
};

}  // namespace ncinterp::sweep
