// The options that choose the machine a command plays on, one definition each, for every
// command that plays a tape (play, cosim, check, board-sim, sweep's grid and the soak read
// the same words): --arch, --rapid, --accel, --events.
// Idea: a user learns an option once; its name, values, default and help are written here
// only, and a command adds it with one call.
#pragma once
#include <CLI/CLI.hpp>
#include <map>
#include <stdexcept>
#include <string>
#include <vector>

#include "interp_ports.h"
#include "operator_events.h"

namespace ncinterp::cli {

// --rapid MM_PER_MIN into `rapid_mm_min`: the machine's rapid rate, at which G00 plays.
inline CLI::Option* add_rapid_option(CLI::App* cmd, double& rapid_mm_min) {
  return cmd
      ->add_option("--rapid", rapid_mm_min,
                   "The machine's rapid rate, mm/min: a G00 traverse's longer axis moves at half "
                   "to all of it (docs/tape-format.md)")
      ->check(CLI::PositiveNumber)
      ->capture_default_str();
}

// --accel MM_PER_S2 into `accel_mm_s2`: the acceleration limit of the feed ramp; 0 (the
// default): no ramps, every block plays at its programmed rate from its first clock.
inline CLI::Option* add_accel_option(CLI::App* cmd, double& accel_mm_s2) {
  return cmd
      ->add_option("--accel", accel_mm_s2,
                   "Acceleration limit, mm/s^2: every block ramps its rate from rest and back to "
                   "rest within it (exact stop), the same pulses in the same order; 0: no ramps "
                   "(docs/motion-control.md)")
      ->check(CLI::NonNegativeNumber)
      ->capture_default_str();
}

// The exit status of a play, check or cosim run that an E-stop or a limit of --events
// ended (README, "Exit codes"): nothing failed, but the program did not run to its end.
inline constexpr int kExitStopped = 5;
// ... that paused at an M00 (or M01 with the optional stop on) with no cycle start to come.
inline constexpr int kExitPaused = 6;

// --events LIST into `events`: the operator's actions, e.g. hold@0.8s,resume@1.2s
// (machine_events() reads it once the clock is known).
inline CLI::Option* add_events_option(CLI::App* cmd, std::string& events) {
  return cmd->add_option("--events", events,
                         "The operator's actions in machine time, comma-separated: hold@Ts (feed "
                         "hold), resume@Ts or start@Ts (cycle start), override=P@Ts (feed override, "
                         "0-200 %), rapid-override=P@Ts (25, 50, 100 %), estop@Ts, limit-x@Ts, "
                         "limit-y@Ts, optional-stop=on@Ts or =off (M01 pauses while on), e.g. "
                         "hold@0.8s,resume@1.2s,override=50@1.5s "
                         "(docs/motion-control.md)");
}

// The --events list at `clock_hz` (parse_events()); an override needs the ramp (--accel), since
// it changes the rate at the acceleration limit. Throws std::invalid_argument.
inline std::vector<OperatorEvent> machine_events(const std::string& list, double clock_hz,
                                                 double accel_mm_s2) {
  std::vector<OperatorEvent> events = parse_events(list, clock_hz);
  if (accel_mm_s2 <= 0 && has_override(events))
    throw std::invalid_argument(
        "--events: an override needs --accel: it changes the rate at the acceleration limit, and "
        "without a limit there are no ramps (docs/motion-control.md)");
  return events;
}

// --arch serial|parallel into `arch` (default: serial, what the boards ship).
inline CLI::Option* add_arch_option(CLI::App* cmd, Arch& arch) {
  static const std::map<std::string, Arch> kArchs = {{"serial", Arch::kSerial},
                                                     {"parallel", Arch::kParallel}};
  return cmd
      ->add_option("--arch", arch,
                   "Interpolator microarchitecture, for the golden model and the RTL alike: "
                   "serial (bit-serial DDA, 2P clocks per iteration: what the boards ship) or "
                   "parallel (one DDA iteration per clock)")
      ->transform(CLI::CheckedTransformer(kArchs))
      ->default_str(arch_name(arch));
}

}  // namespace ncinterp::cli
