// Pulse-path monitor: watches the interpolator's outputs clock by clock, follows the tape's
// blocks, measures every pulse position against the programmed block (interpolator error)
// and the part contour (total error), and checks every pulse.
// Idea: the machine's tool position is the integral of the step/dir pulses, so the checker
// keeps its own position from the pulses and judges each pulse by rules derived from the
// tape and the documented timing (docs/verification.md lists them), never from an engine:
//   counter   pos_x_o/pos_y_o equal the integrated pulses (a counter never moves alone);
//   idle      no pulse while no block plays;
//   direction while a block plays, dir_*_o is the sign of its increment (1 for 0 on a
//             line, as section 5.1 says) and every pulse goes that way;
//   count     an axis never emits more pulses than its increment;
//   schedule  (G01 blocks) the pulse count of each axis equals the documented DDA count
//             for the iterations due by this clock (line_schedule.h): a lost, extra, early
//             or late pulse is reported at the clock where it happens; with the feed ramp
//             (CheckerOptions::accel_step) the counts at each pulse are those of the
//             DDA's next pulsing iteration: the pulses without ramps, in their order;
//             (arcs) the pulses at each clock are those of the circle DDA's next pulsing
//             iteration (dda_circle.h, replayed from the block's words): its order, at any
//             times (the arcs' timing is the engines' and the cosim's);
//   bound     each pulse position is within the interpolator's bound of the block's path;
//   endpoint  at the block's end each axis has emitted exactly its increment;
//   duration  (G01 blocks) the block lasts the documented ceil(M/F) (2^k + 1 saturated),
//             at least that with the ramp (at a feed override of up to P > 100 %, at least
//             that times 100 % / P), and feed_saturated_o says whether F << k >= M;
//   held      no pulse while the operator holds (--events), once the machine can be at
//             rest: from the hold's press plus CheckerOptions::hold_settle clocks (the
//             ramp down from the fastest rate and a serial iteration in flight) to start;
//   accel     (with the ramp) the iteration rate changes by at most du / M per clock^2
//             (an axis's acceleration: that times |d| / N, N the block's iterations, on
//             average over an arc), measured from the times of the iterations that pulse,
//             plus the allowance of one clock per iteration time (a strobe comes on the
//             first clock after the phase passes M); on an arc also its centripetal
//             acceleration v^2 / R, v measured over spans of 64 BLU of chord (the chord
//             less the bound at each end, over the span's clocks plus one), at most the
//             limit times the square of the largest feed override (the first stage's arc
//             feed, `tape --accel`, keeps v <= sqrt(A R));
//   stop      after an E-stop or a limit (--events; CheckerOptions::stop_cycle) no pulse
//             comes after the clock of its press, and the machine shows the error with
//             the input's code from that clock, naming the block playing;
//   sequence  blocks load in tape order, block_n_o showing each block's N;
//   complete  the run reaches the end of program with every block played (or, with a
//             stop, ends on it).
// Each rule reports its first failure per block with the block, the clock and the position.
#pragma once
#include <cstdint>
#include <string>
#include <utility>
#include <vector>

#include "dda_circle.h"
#include "interp_ports.h"
#include "line_schedule.h"
#include "programmed_path.h"
#include "reference_contour.h"

namespace ncinterp::checker {

enum class Rule : uint8_t {
  kCounter,
  kIdlePulse,
  kDirection,
  kPulseCount,
  kSchedule,
  kPathBound,
  kEndpoint,
  kDuration,
  kSequence,
  kComplete,
  kHeld,
  kAcceleration,
  kStop,
  kTool,
  kTotalError,  // set by the caller's tolerance check, not by observe()
};
const char* rule_name(Rule rule);

struct Violation {
  Rule rule;
  size_t block = 0;    // index into the programmed blocks (SIZE_MAX: none)
  uint32_t n = 0;      // the block's N
  uint64_t cycle = 0;
  GridPoint position;  // tool position at that clock, BLU from the tape start
  std::string detail;
};

// Max, RMS and where the max is, of an error sampled at pulses.
struct ErrorStat {
  double max = 0.0;
  double sum_sq = 0.0;
  uint64_t count = 0;
  uint64_t cycle = 0;     // where the max is
  GridPoint position;
  size_t block = 0;
  void add(double e, uint64_t at_cycle, GridPoint at, size_t in_block);
  void merge(const ErrorStat& o);
  double rms() const;
};

struct BlockResult {
  bool played = false;     // loaded
  bool finished = false;   // ended (next load or busy falling)
  bool rapid = false;      // a G00 block: a traverse, no total error
  bool tool = false;       // the tool output during its pulses (M03 before it, no M05 yet)
  uint64_t load_cycle = 0, end_cycle = 0;
  uint64_t pulses[2] = {0, 0};
  ErrorStat path;          // distance to the programmed block
  ErrorStat total;         // distance to the contour (not rapid)
  // Offset: largest distance of the centre outside the equidistant where the cutter reaches
  // the part from elsewhere on its path (vertices turning away from the part), BLU.
  double outside_excursion = 0.0;
  double bound = 0.0;      // interpolator bound used for the path rule, BLU
  bool saturated = false;  // lines: needs more iterations than clocks (documented)
  // With the ramp: each axis's largest acceleration measured (BLU per clock^2), and the
  // largest ratio of a measured acceleration to the limit plus its allowance.
  double accel[2] = {0.0, 0.0};
  double accel_ratio = 0.0;
  double centripetal = 0.0;  // arcs: the largest v^2 / R measured (BLU per clock^2)
  double ideal_clocks = 0.0;  // 1/F in clocks
  uint64_t clocks = 0;        // measured, load edge to the next load edge / busy falling
  double feed_relative_error() const {
    return ideal_clocks > 0 ? (static_cast<double>(clocks) - ideal_clocks) / ideal_clocks : 0.0;
  }
};

// One pulse position, for plots and for error-along-the-path figures.
struct PulseSample {
  uint64_t cycle;
  uint32_t block;  // index
  GridPoint position;
  float path_error, total_error;  // BLU; total < 0: not measured (rapid)
};

struct CheckerOptions {
  uint64_t feed_modulus = 60ull * 1000000ull * 1000ull;  // M = 60 f_clk 10^FeedFracDigits
  bool schedule = true;        // the schedule and duration rules for line blocks (arcs: order)
  unsigned inc_width = 16;     // W (InterpConfig::inc_width): an arc's circle DDA at it
  unsigned lead_bits = 0;      // log2 of the DDA's clocks per iteration (line_schedule.h)
  uint64_t rapid_step = 0;     // S of a G00 block (InterpConfig::rapid_step_on_port())
  // The feed ramp's step du (InterpConfig::accel_step; 0: no ramps). Ramped, a line's
  // schedule rule checks the order of its pulses (the DDA's, at any times), its duration
  // rule that it takes at least the programmed time, and the acceleration rule holds.
  uint64_t accel_step = 0;
  bool operator_holds = false;  // the run has the operator's presses (--events): as ramped
  // The largest feed override of the events, in units of 1 / kOverrideOne (at least 100 %):
  // a block may play that much faster than programmed.
  uint32_t max_override = kOverrideOne;
  // The held stretches (press of hold, press of start; UINT64_MAX: none), and the clocks
  // after a hold's press in which pulses may still come.
  std::vector<std::pair<uint64_t, uint64_t>> holds;
  uint64_t hold_settle = 0;
  // The first stop (E-stop, a limit switch) of the events: the clock of its press and the
  // error code it raises (UINT64_MAX: none).
  uint64_t stop_cycle = UINT64_MAX;
  uint8_t stop_code = 0;
  // Bound of the pulse path around an arc block, measured against the radius changing
  // linearly from R0 to R1: arc_path_bound(R0, R1, arc_bound_blu) (path_bounds.h;
  // docs/circle-dda.md 3.2: 0.88 BLU, measured on every good arc up to W = 7 and 100000
  // random arcs at W = 16).
  double arc_bound_blu = kCircleDdaBound;
  bool keep_pulses = true;     // record every pulse (plots, error along the path)
  size_t max_violations = 1000;  // details kept; all are counted
};

// Where a feed hold brought the machine to rest: its last pulse after the press (or the
// press itself, when no pulse came after it) and the position there.
struct HoldStop {
  uint64_t pressed = 0, resumed = UINT64_MAX;  // the hold's press, the next start's
  uint64_t at_rest = 0;                        // the clock of the last pulse in between
  GridPoint position;                          // BLU from the tape start, at rest
};

class TrajectoryChecker {
 public:
  // reference may be null (no contour: only the interpolator's error and the rules); with
  // a cutter radius the checker gives it the programmed cutter path.
  TrajectoryChecker(std::vector<ProgrammedBlock> blocks, ReferenceContour* reference,
                    const CheckerOptions& options);

  // The outputs after reset (cycle 0), then after every clock edge, in order.
  void observe(uint64_t cycle, const InterpOutputs& o);
  // Event jumping (engine_run.h): the clocks after the last observed one up to `cycle`
  // had the outputs last observed (o), with no step: what observe() would do for each of
  // them. quiet_limit(): the last cycle that may be passed so; a clock the checker must
  // see by itself (an iteration edge or the end of a G01 block by the documented timing)
  // comes after it.
  void observe_quiet(uint64_t cycle, const InterpOutputs& o);
  uint64_t quiet_limit() const;
  // A clock after the run ended on its stop (engine_run.h's run_past_stop()): a step pulse
  // breaks the stop rule.
  void observe_after_stop(uint64_t cycle, const InterpOutputs& o);
  // End of the run, with the last outputs observed: the complete rule, an engine's tape
  // error. (The checker keeps per clock only what the next clock needs, not a copy of
  // the outputs: see engine_run.h.)
  void finish(const InterpOutputs& last);
  // The tolerance rule: every block whose total error exceeds tol_blu, at its maximum.
  void check_tolerance(double tol_blu);

  const std::vector<ProgrammedBlock>& blocks() const { return blocks_; }
  const std::vector<BlockResult>& results() const { return results_; }
  const std::vector<Violation>& violations() const { return violations_; }
  uint64_t violation_count() const { return violation_count_; }
  const std::vector<PulseSample>& pulses() const { return pulses_; }  // if keep_pulses
  uint64_t pulse_count() const { return pulse_count_; }  // clocks with a step on any axis
  const ErrorStat& path_error() const { return path_; }
  const ErrorStat& total_error() const { return total_; }
  GridPoint position() const { return pos_; }
  const std::vector<HoldStop>& hold_stops() const { return hold_stops_; }  // one per hold
  // The run ended on its stop (CheckerOptions::stop_cycle) as the stop rule asks; the
  // machine stood at position() from then on.
  bool stopped() const { return stopped_; }
  // The run ended paused (M00, or M01 with the switch on) with no cycle start to come.
  bool paused() const { return paused_; }
  uint64_t cycles() const { return last_cycle_; }
  uint64_t gap_clocks() const { return gap_clocks_; }

 private:
  // load_known: the load shows on the outputs or at its documented clock; false: it was
  // placed at the block's first pulse (same_n_by_pulses()), so its duration is unknown.
  void start_block(uint64_t cycle, const InterpOutputs& o, bool load_known = true);
  void end_block(uint64_t cycle);
  void on_pulse(uint64_t cycle, const bool step[2], const bool dir[2]);
  void check_schedule(uint64_t cycle, bool pulsed);
  void check_order(uint64_t cycle);           // the schedule rule with the ramp
  void check_arc_order(uint64_t cycle, const bool step[2]);  // the schedule rule on an arc
  void check_acceleration(uint64_t cycle);    // at an iteration that pulses, with the ramp
  void check_centripetal(uint64_t cycle);     // on an arc, at a pulse, with the ramp
  // The ramp or the operator's holds move the iterations off the documented clocks: the
  // schedule rule checks their order, the duration rule a lower bound.
  bool ramped() const { return options_.accel_step > 0 || options_.operator_holds; }
  // Two consecutive blocks with the same N (a tape without N words) show no load on the
  // outputs. A straight block's documented time places the load where nothing moves it;
  // otherwise (the ramp, holds, arcs) the playing block is over once all its pulses have
  // come, and the next pulse is the next block's.
  bool same_n_next() const;
  // Block i is a still block (an M word alone, no pulses) with its predecessor's N: it shows
  // no load of its own, and the next load of another N, or the program's end, passes over
  // it (pass_over(): played and finished at that clock).
  bool still_with_last_n(size_t i) const;
  void pass_over(size_t i, uint64_t cycle);
  bool same_n_by_time() const;
  bool same_n_by_pulses() const;
  void report(Rule rule, uint64_t cycle, std::string detail);
  void report_pulse_after_stop(uint64_t cycle);

  std::vector<ProgrammedBlock> blocks_;
  std::vector<BlockResult> results_;
  ReferenceContour* reference_;
  CheckerOptions options_;

  bool started_ = false;
  BlockLoadWatch prev_;          // the previous clock's outputs
  uint64_t last_cycle_ = 0;
  GridPoint pos_;                // integrated pulses
  uint64_t gap_clocks_ = 0;

  // The block playing.
  bool active_ = false;
  size_t cur_ = 0;               // index of the playing (or last played) block
  size_t loaded_ = 0;            // blocks loaded so far
  int64_t progress_[2] = {0, 0}; // pulses along the block's direction, per axis
  bool expected_dir_[2] = {true, true};
  bool load_known_ = true;       // see start_block
  std::vector<HoldStop> hold_stops_;
  bool stopped_ = false, paused_ = false;
  LineSchedule schedule_;
  // A straight block's feed step S and its schedule (line_schedule.h) on this machine.
  unsigned __int128 step_of(const ProgrammedBlock& b) const;
  LineSchedule schedule_of(const ProgrammedBlock& b) const;
  uint64_t iterations_ = 0;      // documented iterations due by the last clock
  uint64_t block_iterations_ = 0;  // the block's N: 2^k, or an arc's (a dry run, with the ramp)
  CircleDda arc_dda_;            // an arc's DDA, replayed an iteration ahead of its pulses
  // With the ramp: the last two pulsing iterations of the block (index, cycle).
  uint64_t event_j_[2] = {0, 0}, event_t_[2] = {0, 0};
  // The centripetal rule's span on an arc: where and when it began (start_block(): the
  // block's start and load).
  GridPoint arc_span_from_;
  uint64_t arc_span_at_ = 0;
  static constexpr double kCentripetalSpan = 64.0;  // BLU
  int events_ = 0;
  uint32_t reported_ = 0;        // rules already reported in this block (bit per rule)

  std::vector<Violation> violations_;
  uint64_t violation_count_ = 0;
  std::vector<PulseSample> pulses_;
  uint64_t pulse_count_ = 0;
  ErrorStat path_, total_;
};

}  // namespace ncinterp::checker
