// One check of a tape: read it back, play it on an engine clock by clock, and let the
// trajectory checker judge every pulse against the tape and the contour.
// Idea: everything `ncinterp check`, the regression and the soak need, in one call: the
// programmed path comes from the software tape reader, the contour from the first stage's
// reader (the caller passes it in), the pulses from the golden model or the verilated RTL.
#pragma once
#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <vector>

#include "engine_run.h"
#include "firststage.h"
#include "geometry/contour.h"
#include "interp_top.h"
#include "operator_events.h"
#include "reference_contour.h"
#include "tape/tape.h"
#include "trajectory_checker.h"

namespace ncinterp::checker {

// True when this build has the verilated RTL harness.
bool rtl_available();

struct CheckSetup {
  tape::Format format;             // how to read the tape (BLU, register widths)
  double clock_hz = 1e6;
  double reader_cps = 1000.0;      // tape reader, characters per second
  unsigned pos_width = 32;         // the position counters' width (InterpConfig::pos_width)
  Arch arch = Arch::kSerial;       // the microarchitecture both engines play
  double rapid_mm_min = kDefaultRapidMmMin;  // the machine's rapid rate (G00)
  double accel_mm_s2 = 0;          // the feed ramp's limit (0: no ramps)
  std::vector<OperatorEvent> events;  // the operator's presses (--events)
  EngineKind engine = EngineKind::kGolden;
  double tol_mm = 0.01;            // delta: the total error's bound
  // Absolute grid point of the tape start (mm); unset: the contour's start on the grid
  // (refused with a cutter radius: the offset path starts elsewhere).
  std::optional<firststage::Vec2> start_mm;
  double cutter_radius_mm = 0.0;
  bool cutter_left = true;
  bool keep_pulses = true;
  bool schedule = true;            // documented-timing rules for line blocks
  double arc_bound_blu = kCircleDdaBound;  // see CheckerOptions
  uint64_t max_cycles = 0;         // 0: enough for the program (estimated from the tape)
  // Golden engine: tick every clock instead of passing the quiet ones in one step
  // (run_engine_jumping, engine_run.h); the verdict and the report are the same.
  bool every_clock = false;
  // Golden engine only: a fault injected through the model's test hook.
  std::optional<GoldenInterp::Fault> fault;
  // Called every 2^22 clocks with (clocks so far, clock budget): progress display.
  std::function<void(uint64_t, uint64_t)> progress;
};

struct CheckOutcome {
  tape::Program program;
  std::unique_ptr<ReferenceContour> reference;  // null without a contour
  std::unique_ptr<TrajectoryChecker> checker;
  RunEnd run;
  double seconds = 0.0;     // wall time of the engine run with the checker
  double tol_blu = 0.0;
  double blu_mm = 0.001;
  // With the ramp and no operator: the feed plan's cycle time at exact stop (feed_plan.h),
  // which the run confirms from its first block's load on (check_report.h).
  std::optional<double> planned_seconds;
  // No rule failed and the total error is within the tolerance.
  bool passed() const { return checker && checker->violation_count() == 0; }
};

double blu_of(const tape::Format& format);
// Sets what a tape the first stage made with options o tells the checker: its format, the
// tolerance, the cutter and the tape's start (grid point, BLU), as `ncinterp tape` wrote them.
void match_first_stage(CheckSetup& s, const firststage::FirstStageOptions& o, firststage::GridPoint start);
// The tape start's grid point: setup.start_mm, else the contour's start rounded to the grid.
GridPoint tape_start(const firststage::Contour* contour, const CheckSetup& setup);

// Throws tape::TapeFormatError for a bad tape, std::invalid_argument for bad options.
CheckOutcome run_check(const std::vector<uint8_t>& frames, const firststage::Contour* contour,
                       const CheckSetup& setup);

}  // namespace ncinterp::checker
