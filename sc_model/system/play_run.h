// One `play` run: a tape through the SystemC system model with the golden or RTL engine.
// Idea: the caller loads the tape and reads it back (tape::parse_frames_partial) and gets
// back everything the monitors measured; the VCD, if asked for, is written to a temporary
// file beside the target and renamed into place only when the program played to its end
// (M02/M30): a bad tape or a run cut off by the cycle limit leaves no VCD behind.
// SystemC cannot be restarted: run_play may be called once per process.
#pragma once
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "play_monitor.h"
#include "interp_ports.h"
#include "operator_events.h"
#include "atomic_file.h"
#include "tape.h"
#include "vcd_window.h"

namespace ncinterp::system {

struct PlayOptions {
  EngineKind engine = EngineKind::kGolden;
  Arch arch = Arch::kSerial;
  double rapid_mm_min = kDefaultRapidMmMin;
  double accel_mm_s2 = 0;  // the feed ramp's limit; 0: none
  std::vector<OperatorEvent> events;  // the operator's presses (--events)
  double clock_hz = 1e6;
  double reader_cps = 1000;  // tape reader, characters (frames) per second
  std::string vcd_path;      // empty: no VCD
  // When set, the VCD goes to this file reserved by the caller (an OutputSet), which also
  // commits it: run_play then only sets vcd_written (the VCD is complete and wanted).
  AtomicOutputFile* vcd_file = nullptr;
  std::optional<VcdBound> vcd_from, vcd_to;
  uint64_t max_cycles = 0;   // 0: a safe bound computed from the tape
  bool every_clock = false;  // golden engine: no event jumping (SystemSetup::every_clock)
  std::function<void(uint64_t cycle, size_t blocks_done, size_t blocks)> progress;
  // Called once before the simulation when a VCD is asked for, with its estimated size
  // (vcd_size_estimate): the CLI warns about a large file before writing it.
  std::function<void(uint64_t bytes, uint64_t cycles)> vcd_estimate;
};

struct PlayResult {
  PlaySummary summary;
  InterpConfig config;
  double clock_hz = 0;
  double accel_mm_s2 = 0;  // the feed ramp's limit (0: none)
  double reader_cps = 0;
  uint64_t cycles_per_frame = 0;
  size_t frames = 0;
  size_t blocks_on_tape = 0;  // motion blocks the software reader accepted
  uint64_t frames_taken = 0;
  uint64_t max_cycles = 0;
  bool limit_reached = false;
  std::string vcd_path;  // as asked for (empty: none)
  CycleWindow vcd_window;
  bool vcd_written = false;  // committed, or, with vcd_file, complete and to be committed
  double wall_seconds = 0;
  // The program played to its end (done), within the cycle limit.
  bool ok() const { return summary.done && !summary.error && !limit_reached; }
  // An E-stop or a limit switch (--events) ended the run.
  bool stopped() const { return summary.error && is_stop_error(summary.error_code); }
};

// A cycle limit no correct engine reaches on this tape: reading every frame, then every
// block at its programmed or saturated duration, doubled, plus a margin.
// Estimated size of a VCD of `cycles` clocks of this engine: measured bytes per clock of a
// whole-part VCD (docs/waves.md, "VCD size"), so a rough figure, right within a factor ~2.
uint64_t vcd_size_estimate(EngineKind engine, uint64_t cycles);

uint64_t cycle_limit_for(const tape::Program& program, size_t frames, uint64_t cycles_per_frame,
                         const InterpConfig& cfg);

// Throws std::runtime_error for options that cannot run (no RTL in this build, a VCD that
// cannot be created, a window naming a block that never plays, a window after the end).
PlayResult run_play(const std::vector<uint8_t>& frames, const tape::Program& program,
                    const PlayOptions& options);

}  // namespace ncinterp::system
