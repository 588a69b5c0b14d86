// Pulse-path monitor (see trajectory_checker.h).
#include "trajectory_checker.h"

#include "arc_geometry.h"
#include "path_bounds.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>

namespace ncinterp::checker {
namespace {

const char* axis_name(int a) { return a == 0 ? "X" : "Y"; }

std::string point_text(GridPoint p) {
  return "(" + std::to_string(p.x) + ", " + std::to_string(p.y) + ")";
}

// Slack for comparing a floating distance with a bound (both computed from integers).
constexpr double kBoundSlack = 1e-9;

// The schedule and duration rules hold for straight blocks: the documented L1 timing, a G01
// block's at its F, a G00 block's at the machine's rapid step (CheckerOptions::rapid_step).
// An arc's geometry (direction, count, bound, endpoint) and its pulses' order are checked.
bool timed(const ProgrammedBlock& b) { return !b.is_arc(); }

}  // namespace

const char* rule_name(Rule rule) {
  switch (rule) {
    case Rule::kCounter: return "counter";
    case Rule::kIdlePulse: return "idle";
    case Rule::kDirection: return "direction";
    case Rule::kPulseCount: return "count";
    case Rule::kSchedule: return "schedule";
    case Rule::kPathBound: return "bound";
    case Rule::kEndpoint: return "endpoint";
    case Rule::kDuration: return "duration";
    case Rule::kSequence: return "sequence";
    case Rule::kComplete: return "complete";
    case Rule::kHeld: return "held";
    case Rule::kStop: return "stop";
    case Rule::kTool: return "tool";
    case Rule::kAcceleration: return "accel";
    case Rule::kTotalError: return "tolerance";
  }
  return "?";
}

void ErrorStat::add(double e, uint64_t at_cycle, GridPoint at, size_t in_block) {
  if (count == 0 || e > max) {
    max = e;
    cycle = at_cycle;
    position = at;
    block = in_block;
  }
  sum_sq += e * e;
  ++count;
}

void ErrorStat::merge(const ErrorStat& o) {
  if (o.count == 0) return;
  if (count == 0 || o.max > max) {
    max = o.max;
    cycle = o.cycle;
    position = o.position;
    block = o.block;
  }
  sum_sq += o.sum_sq;
  count += o.count;
}

double ErrorStat::rms() const { return count ? std::sqrt(sum_sq / static_cast<double>(count)) : 0.0; }

unsigned __int128 TrajectoryChecker::step_of(const ProgrammedBlock& b) const {
  InterpConfig machine;
  machine.rapid_step = options_.rapid_step;
  machine.modulus_width = 64;  // the option holds the port's value already
  return line_step(b.tape, machine);
}

LineSchedule TrajectoryChecker::schedule_of(const ProgrammedBlock& b) const {
  return LineSchedule(static_cast<uint64_t>(std::llabs(b.tape.dx)), static_cast<uint64_t>(std::llabs(b.tape.dy)),
                      step_of(b), options_.feed_modulus, options_.lead_bits);
}

TrajectoryChecker::TrajectoryChecker(std::vector<ProgrammedBlock> blocks,
                                     ReferenceContour* reference, const CheckerOptions& options)
    : blocks_(std::move(blocks)), reference_(reference), options_(options) {
  results_.resize(blocks_.size());
  bool tool = false;  // the tool output the tape's M03 and M05 ask for
  for (size_t k = 0; k < blocks_.size(); ++k) {
    const ProgrammedBlock& b = blocks_[k];
    BlockResult& r = results_[k];
    r.rapid = b.is_rapid();  // a G00 block on the tape is a traverse; every other one cuts
    // M03 switches the tool on as its block starts, M05 off when its block's motion ends.
    tool = tool || b.tape.tool_on;
    r.tool = tool;
    tool = tool && !b.tape.tool_off;
    r.bound = b.is_arc() ? arc_path_bound(norm(to_vec(b.start) - b.centre), norm(to_vec(b.end) - b.centre),
                                          options_.arc_bound_blu)
                         : line_path_bound(b.tape.dx, b.tape.dy);
    r.ideal_clocks = b.tape.feed ? static_cast<double>(options_.feed_modulus) /
                                       static_cast<double>(b.tape.feed)
                                 : 0.0;
    if (timed(b)) {
      const LineSchedule s = schedule_of(b);
      r.saturated = s.saturated();
      // M 2^k / S: for a G01 block M / F; a G00 block has no F, its S is the rapid step.
      const double step = static_cast<double>(step_of(b));
      r.ideal_clocks =
          step > 0 ? std::ldexp(static_cast<double>(options_.feed_modulus), static_cast<int>(s.k())) / step : 0.0;
    }
  }
  if (reference_ && reference_->radius_blu() > 0) {
    std::vector<bool> rapid;
    std::vector<double> bounds;
    for (const BlockResult& r : results_) rapid.push_back(r.rapid), bounds.push_back(r.bound);
    reference_->set_tool_path(blocks_, rapid, bounds);
  }
  for (const auto& [hold, start] : options_.holds) hold_stops_.push_back({hold, start, hold, {}});
}

void TrajectoryChecker::report(Rule rule, uint64_t cycle, std::string detail) {
  // First failure of each rule per block (and per stretch between blocks).
  const uint32_t bit = 1u << static_cast<unsigned>(rule);
  if (reported_ & bit) return;
  reported_ |= bit;
  ++violation_count_;
  if (violations_.size() >= options_.max_violations) return;
  Violation v;
  v.rule = rule;
  const bool any_block = loaded_ > 0 && cur_ < blocks_.size();
  v.block = any_block ? cur_ : SIZE_MAX;
  v.n = any_block ? blocks_[cur_].tape.n : 0;
  v.cycle = cycle;
  v.position = pos_;
  v.detail = std::move(detail);
  violations_.push_back(std::move(v));
}

void TrajectoryChecker::observe(uint64_t cycle, const InterpOutputs& o) {
  if (!started_) {
    started_ = true;
    prev_.keep(o);
    pos_ = {o.pos_x, o.pos_y};
    last_cycle_ = cycle;
    return;
  }
  last_cycle_ = cycle;
  const bool step[2] = {o.step_x, o.step_y};
  const bool dir[2] = {o.dir_x, o.dir_y};
  for (int a = 0; a < 2; ++a)
    if (step[a]) (a == 0 ? pos_.x : pos_.y) += dir[a] ? 1 : -1;

  // Block boundaries: a load shows as busy rising or block_n_o changing; two consecutive
  // blocks with the same N are told apart by the documented block time or by the pulses.
  // Between the last pulse of the one and the first of the other (same_n_by_pulses()) the
  // outputs may already be the next block's: the direction and saturation rules wait.
  const bool pulsed = step[0] || step[1];
  bool load = prev_.loads(o);
  if (!load && o.busy && same_n_by_time() && cycle == results_[cur_].load_cycle + schedule_.duration())
    load = true;
  const bool between = !load && o.busy && same_n_by_pulses();
  if (active_ && (load || !o.busy || (between && pulsed))) end_block(cycle);
  if (load || (between && pulsed)) start_block(cycle, o, !between);
  if (loaded_ > 0 && !o.busy && !o.done && !o.error) ++gap_clocks_;

  if (o.pos_x != pos_.x || o.pos_y != pos_.y)
    report(Rule::kCounter, cycle,
           "position counters show " + point_text({o.pos_x, o.pos_y}) + ", the pulses add up to " +
               point_text(pos_));

  if (active_) {
    // The direction outputs are held for the whole block.
    const ProgrammedBlock& b = blocks_[cur_];
    const int64_t d[2] = {b.tape.dx, b.tape.dy};
    const bool waiting = between && !pulsed;
    for (int a = 0; a < 2; ++a) {
      const bool known = (!b.is_arc() || d[a] != 0) && !waiting;
      if (known && dir[a] != expected_dir_[a])
        report(Rule::kDirection, cycle,
               std::string("dir_") + (a == 0 ? "x" : "y") + "_o = " + (dir[a] ? "1" : "0") +
                   " while the block moves " + axis_name(a) + " by " + std::to_string(d[a]));
    }
    if (pulsed) on_pulse(cycle, step, dir);
    // At a stop's clock the tool goes off with the error, while that clock may still pulse
    // (the stop rule allows none after it).
    if (pulsed && o.tool != results_[cur_].tool && cycle < options_.stop_cycle)
      report(Rule::kTool, cycle,
             std::string("tool_o = ") + (o.tool ? "1" : "0") + " at a pulse of a block the tape has the tool " +
                 (results_[cur_].tool ? "on (after M03)" : "off"));
    if (options_.schedule && b.is_arc() && pulsed) check_arc_order(cycle, step);
    if (options_.schedule && timed(b)) {
      if (!ramped())
        check_schedule(cycle, pulsed);
      else if (pulsed)
        check_order(cycle);
      if (o.feed_saturated != schedule_.saturated() && !waiting)
        report(Rule::kDuration, cycle,
               std::string("feed_saturated_o = ") + (o.feed_saturated ? "1" : "0") +
                   ", documented " +
                   (schedule_.saturated() ? "1 (F << (k + lead) >= M)" : "0 (F << (k + lead) < M)"));
    }
  } else if (pulsed) {
    report(Rule::kIdlePulse, cycle, "step pulse while no block plays");
  }
  if (pulsed && cycle > options_.stop_cycle) report_pulse_after_stop(cycle);
  if (pulsed) {
    for (HoldStop& h : hold_stops_) {
      if (cycle > h.resumed) continue;
      h.position = pos_;  // up to the press, and each pulse while it brakes
      if (cycle > h.pressed) h.at_rest = cycle;
      if (cycle > h.pressed + options_.hold_settle)
        report(Rule::kHeld, cycle,
               "step pulse while held: hold pressed at clock " + std::to_string(h.pressed) + ", start " +
                   (h.resumed == UINT64_MAX ? std::string("never") : "at " + std::to_string(h.resumed)));
    }
  }
  prev_.keep(o);
}

void TrajectoryChecker::observe_quiet(uint64_t cycle, const InterpOutputs& o) {
  if (loaded_ > 0 && !o.busy && !o.done && !o.error) gap_clocks_ += cycle - last_cycle_;
  last_cycle_ = cycle;
}

uint64_t TrajectoryChecker::quiet_limit() const {
  // With the ramp nothing is due at a documented clock: the rules look at the pulses.
  if (!active_ || !options_.schedule || ramped() || !timed(blocks_[cur_])) return UINT64_MAX;
  const uint64_t load = results_[cur_].load_cycle;
  uint64_t next = load + schedule_.duration();  // the same-N load rule looks at this clock
  if (iterations_ < schedule_.iterations()) {
    const uint64_t edge = schedule_.iteration_edge(iterations_ + 1);
    if (edge != UINT64_MAX) next = std::min(next, load + edge);
  }
  return next - 1;
}

bool TrajectoryChecker::same_n_next() const {
  return active_ && cur_ + 1 < blocks_.size() && blocks_[cur_ + 1].tape.n == blocks_[cur_].tape.n;
}

bool TrajectoryChecker::same_n_by_time() const {
  return same_n_next() && options_.schedule && !ramped() && timed(blocks_[cur_]);
}

bool TrajectoryChecker::same_n_by_pulses() const {
  if (!same_n_next() || same_n_by_time()) return false;
  const ProgrammedBlock& b = blocks_[cur_];
  return progress_[0] == std::llabs(b.tape.dx) && progress_[1] == std::llabs(b.tape.dy);
}

bool TrajectoryChecker::still_with_last_n(size_t i) const {
  return blocks_[i].tape.still && i > 0 && blocks_[i - 1].tape.n == blocks_[i].tape.n;
}

void TrajectoryChecker::pass_over(size_t i, uint64_t cycle) {
  results_[i].played = results_[i].finished = true;
  results_[i].load_cycle = results_[i].end_cycle = cycle;
}

void TrajectoryChecker::start_block(uint64_t cycle, const InterpOutputs& o, bool load_known) {
  if (loaded_ >= blocks_.size()) {
    active_ = false;
    report(Rule::kSequence, cycle,
           "block N" + std::to_string(o.block_n) + " loaded after the last block of the tape");
    return;
  }
  cur_ = loaded_++;
  // A still block (an M word alone, no pulses) with its predecessor's N (an M00 line
  // without N carries the last N) shows no load of its own: a load of another N has passed
  // it.
  while (load_known && o.block_n != blocks_[cur_].tape.n && still_with_last_n(cur_) && loaded_ < blocks_.size()) {
    pass_over(cur_, cycle);
    cur_ = loaded_++;
  }
  active_ = true;
  load_known_ = load_known;
  reported_ = 0;
  const ProgrammedBlock& b = blocks_[cur_];
  BlockResult& r = results_[cur_];
  r.played = true;
  r.load_cycle = cycle;
  progress_[0] = progress_[1] = 0;
  expected_dir_[0] = b.is_arc() ? b.tape.dx > 0 : b.tape.dx >= 0;
  expected_dir_[1] = b.is_arc() ? b.tape.dy > 0 : b.tape.dy >= 0;
  iterations_ = 0;
  events_ = 0;
  arc_span_from_ = pos_, arc_span_at_ = cycle;
  if (timed(b)) {
    schedule_ = schedule_of(b);
    block_iterations_ = schedule_.iterations();
  } else {
    r.saturated = o.feed_saturated;  // an arc's S = F N needs the dry run's N: the engine's word
    const ArcGeometry g = arc_geometry(
        ArcWords::from_signed(b.tape.dx, b.tape.dy, b.tape.i, b.tape.j, b.tape.motion == tape::Motion::kArcCcw),
        options_.inc_width);
    arc_dda_.load(g, false, false);
    // N only for the acceleration rule's share (a dry run: as long as the arc's replay).
    block_iterations_ = options_.accel_step > 0 ? arc_dda_.iterations_left() : 0;
  }
  if (o.block_n != b.tape.n)
    report(Rule::kSequence, cycle,
           "block_n_o = " + std::to_string(o.block_n) + " at the load of tape block " +
               std::to_string(cur_ + 1) + " (N" + std::to_string(b.tape.n) + ")");
}

void TrajectoryChecker::end_block(uint64_t cycle) {
  const ProgrammedBlock& b = blocks_[cur_];
  BlockResult& r = results_[cur_];
  r.finished = true;
  r.end_cycle = cycle;
  r.clocks = cycle - r.load_cycle;
  const int64_t d[2] = {b.tape.dx, b.tape.dy};
  for (int a = 0; a < 2; ++a) {
    if (progress_[a] != std::llabs(d[a]))
      report(Rule::kEndpoint, cycle,
             std::string("axis ") + axis_name(a) + " moved " +
                 std::to_string(d[a] >= 0 ? progress_[a] : -progress_[a]) + " BLU, programmed " +
                 std::to_string(d[a]));
  }
  // Overridden faster, a block's rate is at most P / 100 % of its S: the bound shrinks by that,
  // less a clock for the rounding of ceil(M/F).
  const uint64_t shortest =
      options_.max_override > kOverrideOne
          ? (schedule_.duration() - 1) * kOverrideOne / options_.max_override
          : schedule_.duration();
  if (options_.schedule && timed(b) && load_known_ &&
      (ramped() ? r.clocks < shortest : r.clocks != schedule_.duration()))
    report(Rule::kDuration, cycle,
           "block took " + std::to_string(r.clocks) + " clocks, documented " +
               (ramped() ? "at least " : "") + std::to_string(shortest));
  active_ = false;
  reported_ = 0;
}

void TrajectoryChecker::on_pulse(uint64_t cycle, const bool step[2], const bool dir[2]) {
  const ProgrammedBlock& b = blocks_[cur_];
  BlockResult& r = results_[cur_];
  ++pulse_count_;
  const int64_t d[2] = {b.tape.dx, b.tape.dy};
  for (int a = 0; a < 2; ++a) {
    if (!step[a]) continue;
    ++r.pulses[a];
    const bool along = d[a] != 0 ? dir[a] == (d[a] > 0) : dir[a];
    progress_[a] += along ? 1 : -1;
    if (!along && d[a] != 0)
      report(Rule::kDirection, cycle,
             std::string("pulse on ") + axis_name(a) + " against the block's direction");
    if (std::llabs(progress_[a]) > std::llabs(d[a]) || r.pulses[a] > static_cast<uint64_t>(std::llabs(d[a])))
      report(Rule::kPulseCount, cycle,
             std::string("axis ") + axis_name(a) + ": pulse " + std::to_string(r.pulses[a]) +
                 " of a block that moves it by " + std::to_string(d[a]));
  }
  const Vec2 q = to_vec(pos_);
  const double path = distance_to_block(b, q);
  r.path.add(path, cycle, pos_, cur_);
  path_.add(path, cycle, pos_, cur_);
  if (path > r.bound + kBoundSlack)
    report(Rule::kPathBound, cycle,
           "pulse position " + std::to_string(path) + " BLU from the block's path, bound " +
               std::to_string(r.bound));
  float total = -1.0f;
  if (reference_ && !r.rapid) {
    const TotalError e = reference_->measure(q);
    if (e.outside) r.outside_excursion = std::max(r.outside_excursion, e.signed_excess);
    r.total.add(e.error, cycle, pos_, cur_);
    total_.add(e.error, cycle, pos_, cur_);
    total = static_cast<float>(e.error);
  }
  if (options_.keep_pulses)
    pulses_.push_back({cycle, static_cast<uint32_t>(cur_), pos_, static_cast<float>(path), total});
}

void TrajectoryChecker::check_schedule(uint64_t cycle, bool pulsed) {
  const BlockResult& r = results_[cur_];
  bool due = false;
  while (iterations_ < schedule_.iterations() &&
         r.load_cycle + schedule_.iteration_edge(iterations_ + 1) <= cycle) {
    ++iterations_;
    due = true;
  }
  if (!due && !pulsed) return;
  const ProgrammedBlock& b = blocks_[cur_];
  const int64_t d[2] = {b.tape.dx, b.tape.dy};
  for (int a = 0; a < 2; ++a) {
    const uint64_t expected = schedule_.pulses(std::llabs(d[a]), iterations_);
    if (progress_[a] != static_cast<int64_t>(expected))
      report(Rule::kSchedule, cycle,
             std::string("axis ") + axis_name(a) + ": " + std::to_string(progress_[a]) +
                 " pulses, documented " + std::to_string(expected) + " after iteration " +
                 std::to_string(iterations_) + " of " + std::to_string(schedule_.iterations()));
  }
}

void TrajectoryChecker::check_order(uint64_t cycle) {
  // The DDA's next iteration that pulses an axis: an axis of d > 0 with c pulses so far
  // pulses next at the first j with floor((2^(k-1) + j d) / 2^k) > c.
  const ProgrammedBlock& b = blocks_[cur_];
  const uint64_t d[2] = {static_cast<uint64_t>(std::llabs(b.tape.dx)), static_cast<uint64_t>(std::llabs(b.tape.dy))};
  uint64_t next = UINT64_MAX;
  for (int a = 0; a < 2; ++a) {
    const uint64_t c = schedule_.pulses(d[a], iterations_);
    if (d[a] == 0 || c >= d[a]) continue;
    uint64_t j = iterations_ + 1;
    // Solve h + j d >= (c + 1) K for j, then step over the rounding.
    const uint64_t kpow = schedule_.iterations(), half = kpow / 2;
    const unsigned __int128 need = static_cast<unsigned __int128>(c + 1) * kpow;
    if (need > half) j = std::max<uint64_t>(j, static_cast<uint64_t>((need - half + d[a] - 1) / d[a]));
    while (j > iterations_ + 1 && schedule_.pulses(d[a], j - 1) > c) --j;
    while (schedule_.pulses(d[a], j) <= c) ++j;
    next = std::min(next, j);
  }
  if (next == UINT64_MAX || next > schedule_.iterations()) {
    report(Rule::kSchedule, cycle, "a pulse after the block's last pulsing iteration");
    return;
  }
  iterations_ = next;
  for (int a = 0; a < 2; ++a) {
    const uint64_t expected = schedule_.pulses(d[a], iterations_);
    if (progress_[a] != static_cast<int64_t>(expected))
      report(Rule::kSchedule, cycle,
             std::string("axis ") + axis_name(a) + ": " + std::to_string(progress_[a]) +
                 " pulses, the DDA's order gives " + std::to_string(expected) + " at its iteration " +
                 std::to_string(iterations_) + " of " + std::to_string(schedule_.iterations()));
  }
  if (options_.accel_step > 0) check_acceleration(cycle);
}

void TrajectoryChecker::check_arc_order(uint64_t cycle, const bool step[2]) {
  // The circle DDA's next iteration that pulses; its steps must be this clock's.
  CircleDda::Steps s;
  while (!arc_dda_.done() && !s.x && !s.y) {
    s = arc_dda_.iterate();
    ++iterations_;
  }
  if (!s.x && !s.y) {
    report(Rule::kSchedule, cycle, "a pulse after the arc's last pulsing iteration");
    return;
  }
  if (s.x != step[0] || s.y != step[1]) {
    const auto axes = [](bool x, bool y) { return std::string(x ? "X" : "") + (y ? "Y" : ""); };
    report(Rule::kSchedule, cycle,
           "pulses on " + axes(step[0], step[1]) + ", the circle DDA's iteration " + std::to_string(iterations_) +
               " pulses " + axes(s.x, s.y));
  }
  if (options_.accel_step > 0) {
    check_acceleration(cycle);
    check_centripetal(cycle);
  }
}

void TrajectoryChecker::check_acceleration(uint64_t cycle) {
  // Iteration rate over spans between pulsing iterations: r = dj / dt; its change over the
  // time between the middles of two spans is the path's acceleration in iterations per
  // clock^2; an axis of d moves d / 2^k BLU an iteration. Each time lags the ideal one by
  // less than a clock (a strobe comes on the first clock after the phase passes M), so a
  // span's ideal length lies within a clock of dt, which moves r by less than
  // dj / (dt (dt - 1)), and the middles' ideal distance is less than mid + 1/2: the rate
  // changes by at most limit (mid + 1/2) plus those two. A span lasts until
  // dt^3 limit >= 2 dj, which keeps that allowance about the limit itself.
  const double limit = static_cast<double>(options_.accel_step) / static_cast<double>(options_.feed_modulus);
  if (events_ > 0) {
    const double dt = static_cast<double>(cycle - event_t_[events_ - 1]);
    if (dt * dt * dt * limit < 2.0 * static_cast<double>(iterations_ - event_j_[events_ - 1])) return;
  }
  if (events_ == 2) {
    const double j0 = static_cast<double>(event_j_[0]), j1 = static_cast<double>(event_j_[1]);
    const double t0 = static_cast<double>(event_t_[0]), t1 = static_cast<double>(event_t_[1]);
    const double j2 = static_cast<double>(iterations_), t2 = static_cast<double>(cycle);
    const double dt1 = t1 - t0, dt2 = t2 - t1, mid = (dt1 + dt2) / 2;
    const double r1 = (j1 - j0) / dt1, r2 = (j2 - j1) / dt2;
    const double rate_accel = std::abs(r2 - r1) / mid;
    // Strobes come at least 2 clocks apart (the ramp's cap), so dt >= 2.
    const double allowance =
        (limit / 2 + (j1 - j0) / (dt1 * std::max(dt1 - 1, 1.0)) + (j2 - j1) / (dt2 * std::max(dt2 - 1, 1.0))) / mid;
    const ProgrammedBlock& b = blocks_[cur_];
    BlockResult& r = results_[cur_];
    // An axis's share of an iteration: |d| / N (on average, for an arc).
    const double n = static_cast<double>(block_iterations_);
    const double share[2] = {static_cast<double>(std::llabs(b.tape.dx)) / n,
                             static_cast<double>(std::llabs(b.tape.dy)) / n};
    for (int a = 0; a < 2; ++a) r.accel[a] = std::max(r.accel[a], rate_accel * share[a]);
    r.accel_ratio = std::max(r.accel_ratio, rate_accel / (limit + allowance));
    if (rate_accel > limit + allowance)
      report(Rule::kAcceleration, cycle,
             "iteration rate changes by " + std::to_string(rate_accel) + " per clock^2, limit " +
                 std::to_string(limit) + " + allowance " + std::to_string(allowance));
    event_j_[0] = event_j_[1], event_t_[0] = event_t_[1];
  } else {
    ++events_;
  }
  event_j_[events_ - 1] = iterations_;
  event_t_[events_ - 1] = cycle;
}

void TrajectoryChecker::check_centripetal(uint64_t cycle) {
  // The speed over a span of the arc: the chord between two pulse positions over its
  // clocks, the span long enough (kCentripetalSpan BLU, or the radius on a smaller arc) for
  // the pulse positions' distance from the path (the bound, at each end) to matter little.
  // Each time also lags its ideal one by less than a clock, so (chord - 2 bound) / (dt + 1)
  // is below the path's mean speed over the span, and a failure is certain.
  const ProgrammedBlock& b = blocks_[cur_];
  BlockResult& r = results_[cur_];
  const Vec2 from = to_vec(arc_span_from_), to = to_vec(pos_), start = to_vec(b.start);
  const double chord = std::hypot(to.x - from.x, to.y - from.y);
  const double radius = std::hypot(start.x - b.centre.x, start.y - b.centre.y);
  if (chord < std::min(kCentripetalSpan, radius)) return;
  const double dt = static_cast<double>(cycle - arc_span_at_);
  arc_span_from_ = pos_, arc_span_at_ = cycle;
  r.centripetal = std::max(r.centripetal, chord * chord / (dt * dt * radius));
  const double slow = std::max(chord - 2 * r.bound, 0.0) / (dt + 1);
  const double faster = static_cast<double>(options_.max_override) / kOverrideOne;
  const double allowed = static_cast<double>(options_.accel_step) / static_cast<double>(options_.feed_modulus) *
                         faster * faster;
  if (slow * slow / radius > allowed) {
    char times[32];
    std::snprintf(times, sizeof times, "%.2f", slow * slow / radius / allowed);
    report(Rule::kAcceleration, cycle,
           std::string("the arc's centripetal acceleration v^2 / R is at least ") + times +
               " times the limit: its F is too high for the limit (ncinterp tape --accel lowers an arc's "
               "feed to sqrt(A R))");
  }
}

void TrajectoryChecker::report_pulse_after_stop(uint64_t cycle) {
  report(Rule::kStop, cycle,
         "step pulse " + std::to_string(cycle - options_.stop_cycle) + " clock(s) after the stop at clock " +
             std::to_string(options_.stop_cycle));
}

void TrajectoryChecker::observe_after_stop(uint64_t cycle, const InterpOutputs& o) {
  if (o.step_x || o.step_y) report_pulse_after_stop(cycle);
}

void TrajectoryChecker::finish(const InterpOutputs& o) {
  const bool stop_due = last_cycle_ >= options_.stop_cycle;  // the run reached the stop's clock
  if (o.error && o.error_code == options_.stop_code && options_.stop_cycle != UINT64_MAX) {
    // Ended on the stop: at its clock, naming the block playing (or the last played).
    const uint32_t n = loaded_ > 0 ? blocks_[cur_].tape.n : 0;
    if (last_cycle_ != options_.stop_cycle)
      report(Rule::kStop, last_cycle_,
             "the stop's error came at clock " + std::to_string(last_cycle_) + ", the stop at clock " +
                 std::to_string(options_.stop_cycle));
    else if (o.error_block != n)
      report(Rule::kStop, last_cycle_,
             "the stop names block N" + std::to_string(o.error_block) + ", the block playing is N" +
                 std::to_string(n));
    stopped_ = true;
  } else if (stop_due && !o.error) {
    report(Rule::kStop, last_cycle_,
           std::string("the stop at clock ") + std::to_string(options_.stop_cycle) + " did not stop the machine (" +
               tape_error_message(static_cast<TapeError>(options_.stop_code)) + " expected)");
  } else if (o.error) {
    report(Rule::kComplete, last_cycle_,
           "the interpolator stopped on an error: block N" + std::to_string(o.error_block) +
               ", offset " + std::to_string(o.error_offset) + ": " +
               tape_error_message(static_cast<TapeError>(o.error_code)));
  } else if (o.paused) {
    paused_ = true;  // every rule held up to the pause; no cycle start comes to resume it
  } else {
    // Still blocks with their predecessor's N at the tape's end (a cut's M05, an M00 line
    // without N) show no load of their own, and no later load passes them: the end has.
    while (o.done && loaded_ < blocks_.size() && still_with_last_n(loaded_)) pass_over(loaded_++, last_cycle_);
    if (!o.done || loaded_ < blocks_.size())
      report(Rule::kComplete, last_cycle_,
             std::to_string(loaded_) + " of " + std::to_string(blocks_.size()) +
                 " blocks played and " + (o.done ? "done" : "no end of program") + " after " +
                 std::to_string(last_cycle_) + " clocks");
  }
}

}  // namespace ncinterp::checker

namespace ncinterp::checker {

void TrajectoryChecker::check_tolerance(double tol_blu) {
  for (size_t k = 0; k < results_.size(); ++k) {
    const ErrorStat& t = results_[k].total;
    if (t.count == 0 || t.max <= tol_blu) continue;
    ++violation_count_;
    if (violations_.size() >= options_.max_violations) continue;
    violations_.push_back({Rule::kTotalError, k, blocks_[k].tape.n, t.cycle, t.position,
                           "total error " + std::to_string(t.max) + " BLU exceeds the tolerance " +
                               std::to_string(tol_blu) + " BLU"});
  }
}

}  // namespace ncinterp::checker
