// One design point of the sweep, measured: what its parameters cost (synthesis, placement
// on the HX8K and the HX1K) and what they buy (tapes, errors, feed accuracy from the first
// stage + golden model + checker; the register ranges). This is the one per-point code
// path: `--jobs N` runs it on threads, `--run-one KEY` runs it for one job of a plan.
// Idea: the point's parameter names decide where each value goes; every parameter the
// tools do not know by name is an RTL parameter (chparam), so the RTL can grow parameters
// without a change here. A point's key is a content hash of everything its result depends
// on (the point, the inputs' contents, the settings, the model and RTL sources, the tool
// versions), so a result file named by the key is valid wherever and whenever it was made.
#pragma once
#include <functional>
#include <string>
#include <vector>

#include "design_point.h"
#include "rtl_variant.h"
#include "sweep_row.h"
#include "synthesis.h"
#include "tape_measurement.h"

namespace ncinterp::sweep {

// Parameter names the tools understand (any other name: an RTL parameter).
inline constexpr const char* kIncWidth = "IncWidth";
inline constexpr const char* kFeedWidth = "FeedWidth";
inline constexpr const char* kPosWidth = "PosWidth";
inline constexpr const char* kBlu = "blu_mm";
inline constexpr const char* kClock = "clock_hz";
// interp_top's BitSerial (1 = the serial arch, 0 = the parallel one): an RTL parameter that
// the golden model and the RTL variant take too (`--archs`).
inline constexpr const char* kBitSerial = "BitSerial";
// interp_top's CircleMode (1 = lines and arcs, 0 = the lines-only core of the iCEstick): an
// RTL parameter the golden model and the RTL variant take too; a lines-only point's first
// stage cuts every arc as chords (its tapes have no G02/G03), so its error and tape length
// are those of the machine it describes (`--param CircleMode=0,1`).
inline constexpr const char* kCircleMode = "CircleMode";
// IncWidth the golden model and the RTL take.
inline constexpr unsigned kMinWidth = 2;
inline constexpr unsigned kMaxWidth = 32;

struct PointSetup {
  std::vector<SweepInput> inputs;
  MeasureSetup measure;       // the defaults of every parameter a point does not set
  bool synthesis = true;
  SynthesisSetup synth;
  std::string synth_key;      // synthesis_key(synth), when synthesis is on
  bool rtl = true;            // the verilated variant in lock step (IncWidth, BLU, arch points)
  RtlVariantSetup rtl_variant;
  std::string tape_dir;       // tapes for the RTL variant: <tape_dir>/<key>/
};

// What the registers of a point can hold (arithmetic on the parameters, not measured):
// the largest move per block, the position range, and the feed range of the F register
// (inverse time in 10^-3 1/min) for a one-BLU block, with the clock's own limit of one
// step per clock.
struct RegisterRanges {
  double max_move_mm = 0.0;          // (2^IncWidth - 1) BLU
  double pos_range_mm = 0.0;         // +-(2^(PosWidth-1) - 1) BLU
  double feed_min_mm_min = 0.0;      // F = 1 on a one-BLU block
  double feed_max_mm_min = 0.0;      // F = 2^FeedWidth - 1 on a one-BLU block
  double feed_max_clock_mm_min = 0.0;  // one step per clock: 60 * clock_hz BLU/min
};
RegisterRanges register_ranges(const DesignPoint& p, const MeasureSetup& defaults);

struct PointResult {
  DesignPoint point;
  std::string key;
  SweepRow row;             // row.width = the point's IncWidth
  RegisterRanges ranges;
  double seconds = 0.0;     // wall time of run_point (0 for a point never run)
};

// The RTL parameters of a point: IncWidth, FeedWidth, PosWidth as given, FracDigits from
// blu_mm, every unknown name as it is; clock_hz is a port value, not a parameter.
RtlParameters rtl_parameters(const DesignPoint& p);

// A hash of what every point's result depends on besides the point itself; settings are
// the command's options as text, in a fixed order.
std::string setup_hash(const PointSetup& setup, const std::vector<std::string>& settings,
                       const std::vector<std::string>& model_sources);
std::string point_key(const DesignPoint& p, const std::string& setup_hash);

// Measures the point. Never throws for a tool or a too-narrow width: each value is
// measured or carries its reason (a first stage refusing a width keeps its message).
PointResult run_point(const DesignPoint& p, const std::string& key, const PointSetup& setup,
                      const std::function<void(const std::string&)>& stage = nullptr);

}  // namespace ncinterp::sweep
