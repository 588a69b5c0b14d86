// JSON report and text summary of a check (see check_report.h).
#include "check_report.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <sstream>

namespace ncinterp::checker {
namespace {

using nlohmann::json;

struct Frame {
  double blu_mm;
  GridPoint start;
  json xy(GridPoint p) const {
    return {{"x_mm", (start.x + p.x) * blu_mm}, {"y_mm", (start.y + p.y) * blu_mm}};
  }
};

json stat_json(const ErrorStat& s, const TrajectoryChecker& c, const Frame& f) {
  json j = {{"max_blu", s.max}, {"max_mm", s.max * f.blu_mm}, {"rms_blu", s.rms()},
            {"rms_mm", s.rms() * f.blu_mm}, {"samples", s.count}};
  if (s.count) {
    j["at"] = {{"block", c.blocks()[s.block].tape.n}, {"cycle", s.cycle}, {"position", f.xy(s.position)}};
  }
  return j;
}

const char* motion_name(tape::Motion m) { return tape::motion_word(m); }

std::string fmt(const char* format, double v) {
  char buf[64];
  std::snprintf(buf, sizeof buf, format, v);
  return buf;
}

Frame frame_of(const CheckOutcome& o) {
  return {o.blu_mm, o.reference ? o.reference->start() : GridPoint{}};
}

}  // namespace

AccelSummary accel_summary(const TrajectoryChecker& c, const CheckSetup& setup, double blu_mm) {
  AccelSummary s;
  s.limit_mm_s2 = setup.accel_mm_s2;
  const double scale = blu_mm * setup.clock_hz * setup.clock_hz;  // BLU/clock^2 -> mm/s^2
  for (const BlockResult& r : c.results()) {
    for (int a = 0; a < 2; ++a) s.max_mm_s2[a] = std::max(s.max_mm_s2[a], r.accel[a] * scale);
    s.worst_ratio = std::max(s.worst_ratio, r.accel_ratio);
    s.max_centripetal_mm_s2 = std::max(s.max_centripetal_mm_s2, r.centripetal * scale);
  }
  return s;
}

FeedSummary feed_summary(const TrajectoryChecker& c) {
  FeedSummary s;
  for (size_t k = 0; k < c.results().size(); ++k) {
    const BlockResult& r = c.results()[k];
    if (!r.finished || r.rapid) continue;  // a G00 block has no programmed feed
    if (r.saturated) {
      ++s.saturated;
      continue;
    }
    ++s.measured;
    const double e = r.feed_relative_error();
    if (s.worst_block == SIZE_MAX || std::fabs(e) > std::fabs(s.worst_relative_error)) {
      s.worst_relative_error = e;
      s.worst_block = k;
    }
  }
  return s;
}

// The run's time from its first block's load on, which CheckOutcome::planned_seconds
// foretells (the plan has no tape reader).
double playing_seconds(const TrajectoryChecker& c, const CheckSetup& setup) {
  const uint64_t first = c.results().empty() ? 0 : c.results().front().load_cycle;
  return static_cast<double>(c.cycles() - std::min(first, c.cycles())) / setup.clock_hz;
}

json check_report_json(const CheckOutcome& o, const ReportContext& ctx) {
  const TrajectoryChecker& c = *o.checker;
  const Frame f = frame_of(o);
  json j;
  j["tape"] = ctx.tape_file;
  j["contour"] = ctx.contour_file.empty() ? json(nullptr) : json(ctx.contour_file);
  j["engine"] = engine_name(ctx.setup.engine);
  j["arch"] = arch_name(ctx.setup.arch);
  j["accel_mm_s2"] = ctx.setup.accel_mm_s2;
  j["clock_hz"] = ctx.setup.clock_hz;
  j["reader_cps"] = ctx.setup.reader_cps;
  j["blu_mm"] = o.blu_mm;
  j["tol_mm"] = ctx.setup.tol_mm;
  j["cutter_radius_mm"] = ctx.setup.cutter_radius_mm;
  if (ctx.setup.cutter_radius_mm > 0) j["cutter_side"] = ctx.setup.cutter_left ? "left" : "right";
  j["tape_start"] = f.xy({0, 0});
  j["status"] = !o.passed() ? "fail" : c.stopped() ? "stopped" : c.paused() ? "paused" : "pass";
  j["blocks"] = c.blocks().size();
  j["cycles"] = c.cycles();
  j["cycle_seconds"] = static_cast<double>(c.cycles()) / ctx.setup.clock_hz;
  if (o.planned_seconds)
    j["feed_plan"] = {{"planned_seconds", *o.planned_seconds}, {"played_seconds", playing_seconds(c, ctx.setup)}};
  if (ctx.setup.accel_mm_s2 > 0) {
    const AccelSummary a = accel_summary(c, ctx.setup, o.blu_mm);
    j["acceleration"] = {{"limit_mm_s2", a.limit_mm_s2},
                         {"max_mm_s2", {{"x", a.max_mm_s2[0]}, {"y", a.max_mm_s2[1]}}},
                         {"worst_of_limit_and_allowance", a.worst_ratio},
                         {"max_centripetal_mm_s2", a.max_centripetal_mm_s2}};
  }
  j["gap_clocks"] = c.gap_clocks();
  j["run_seconds"] = o.seconds;
  j["done"] = o.run.last.done;
  j["final_position"] = f.xy(c.position());
  if (!c.hold_stops().empty()) {
    // Each feed hold: when it was pressed, when its last pulse came (at rest) and where.
    j["holds"] = json::array();
    for (const HoldStop& h : c.hold_stops())
      j["holds"].push_back({{"pressed_s", static_cast<double>(h.pressed) / ctx.setup.clock_hz},
                            {"at_rest_s", static_cast<double>(h.at_rest) / ctx.setup.clock_hz},
                            {"resumed_s", h.resumed == UINT64_MAX ? json(nullptr)
                                                                  : json(static_cast<double>(h.resumed) / ctx.setup.clock_hz)},
                            {"position", f.xy(h.position)}});
  }
  if (c.stopped())  // the E-stop or limit that ended the run: when, and where it stood
    j["stop"] = {{"code", o.run.last.error_code},
                 {"message", tape_error_message(static_cast<TapeError>(o.run.last.error_code))},
                 {"block", o.run.last.error_block},
                 {"pressed_s", static_cast<double>(c.cycles()) / ctx.setup.clock_hz},
                 {"position", f.xy(c.position())}};
  j["pulse_clocks"] = c.pulse_count();
  j["path_error"] = stat_json(c.path_error(), c, f);
  j["path_error"]["measured_against"] = "the programmed block (chord or arc) from the tape";
  if (o.reference) {
    j["total_error"] = stat_json(c.total_error(), c, f);
    j["total_error"]["measured_against"] =
        ctx.setup.cutter_radius_mm > 0 ? "the offset contour: R - d inside (gouge); outside, the part left uncut at the foot"
                                       : "the part contour";
    double outside = 0.0;
    size_t rapids = 0;
    for (const BlockResult& r : c.results()) outside = std::max(outside, r.outside_excursion), rapids += r.rapid;
    if (ctx.setup.cutter_radius_mm > 0) j["total_error"]["outside_excursion_max_mm"] = outside * o.blu_mm;
    j["total_error"]["rapid_blocks"] = rapids;
  }
  const FeedSummary fs = feed_summary(c);
  j["feed"] = {{"worst_relative_error", fs.worst_relative_error},
               {"blocks_measured", fs.measured},
               {"saturated_blocks", fs.saturated}};
  if (fs.worst_block != SIZE_MAX) {
    const BlockResult& r = c.results()[fs.worst_block];
    j["feed"]["at"] = {{"block", c.blocks()[fs.worst_block].tape.n},
                       {"clocks", r.clocks},
                       {"ideal_clocks", r.ideal_clocks}};
  }
  j["violation_count"] = c.violation_count();
  json vs = json::array();
  std::vector<Violation> sorted = c.violations();
  std::stable_sort(sorted.begin(), sorted.end(),
                   [](const Violation& a, const Violation& b) { return a.cycle < b.cycle; });
  for (const Violation& v : sorted) {
    vs.push_back({{"rule", rule_name(v.rule)},
                  {"block", v.block == SIZE_MAX ? json(nullptr) : json(v.n)},
                  {"cycle", v.cycle},
                  {"position", f.xy(v.position)},
                  {"detail", v.detail}});
  }
  j["violations"] = vs;
  json per = json::array();
  for (size_t k = 0; k < c.blocks().size(); ++k) {
    const ProgrammedBlock& b = c.blocks()[k];
    const BlockResult& r = c.results()[k];
    json e = {{"n", b.tape.n},
              {"motion", motion_name(b.tape.motion)},
              {"dx", b.tape.dx},
              {"dy", b.tape.dy},
              {"feed", b.tape.feed},
              {"played", r.played},
              {"load_cycle", r.load_cycle},
              {"clocks", r.clocks},
              {"ideal_clocks", r.ideal_clocks},
              {"feed_relative_error", r.feed_relative_error()},
              {"saturated", r.saturated},
              {"pulses", {{"x", r.pulses[0]}, {"y", r.pulses[1]}}},
              {"bound_blu", r.bound},
              {"path_error", stat_json(r.path, c, f)}};
    if (b.is_arc()) e["centre"] = {{"i", b.tape.i}, {"j", b.tape.j}};
    if (o.reference) {
      e["rapid"] = r.rapid;
      e["total_error"] = stat_json(r.total, c, f);
      if (r.outside_excursion > 0) e["outside_excursion_mm"] = r.outside_excursion * o.blu_mm;
    }
    per.push_back(std::move(e));
  }
  j["per_block"] = per;
  return j;
}

std::string check_summary_text(const CheckOutcome& o, const ReportContext& ctx) {
  const TrajectoryChecker& c = *o.checker;
  const Frame f = frame_of(o);
  std::ostringstream s;
  auto where = [&](const ErrorStat& e) {
    const double x = (f.start.x + e.position.x) * o.blu_mm, y = (f.start.y + e.position.y) * o.blu_mm;
    return "block N" + std::to_string(c.blocks()[e.block].tape.n) + ", cycle " + std::to_string(e.cycle) +
           ", at (" + fmt("%.3f", x) + ", " + fmt("%.3f", y) + ") mm";
  };
  s << ctx.tape_file << ": " << c.blocks().size() << " blocks, " << c.pulse_count() << " pulse clocks, "
    << c.cycles() << " clocks on the " << engine_name(ctx.setup.engine) << " engine ("
    << arch_name(ctx.setup.arch) << ")\n";
  const ErrorStat& p = c.path_error();
  s << "  interpolator error (to the programmed blocks): max " << fmt("%.4f", p.max * o.blu_mm)
    << " mm (" << fmt("%.3f", p.max) << " BLU), rms " << fmt("%.4f", p.rms() * o.blu_mm) << " mm";
  if (p.count) s << "; max at " << where(p);
  s << "\n";
  if (o.reference) {
    const ErrorStat& t = c.total_error();
    s << "  total error (to the " << (ctx.setup.cutter_radius_mm > 0 ? "offset " : "") << "contour): max "
      << fmt("%.4f", t.max * o.blu_mm) << " mm, rms " << fmt("%.4f", t.rms() * o.blu_mm)
      << " mm, tolerance " << fmt("%.4f", ctx.setup.tol_mm) << " mm";
    if (t.count) s << "; max at " << where(t);
    s << "\n";
  }
  const FeedSummary fs = feed_summary(c);
  s << "  feed: worst block time vs 1/F " << fmt("%+.3g", fs.worst_relative_error * 100) << " %";
  if (fs.worst_block != SIZE_MAX) s << " (block N" << c.blocks()[fs.worst_block].tape.n << ")";
  s << ", " << fs.saturated << " saturated block(s)\n";
  if (ctx.setup.accel_mm_s2 > 0) {
    const AccelSummary a = accel_summary(c, ctx.setup, o.blu_mm);
    s << "  acceleration of the ramp: max X " << fmt("%.1f", a.max_mm_s2[0]) << ", Y "
      << fmt("%.1f", a.max_mm_s2[1]) << " mm/s^2, limit " << fmt("%g", a.limit_mm_s2)
      << " mm/s^2; worst " << fmt("%.2f", a.worst_ratio) << " of limit + allowance\n";
    if (a.max_centripetal_mm_s2 > 0)
      s << "  arcs: centripetal acceleration v^2/R max " << fmt("%.1f", a.max_centripetal_mm_s2) << " mm/s^2\n";
  }
  if (o.planned_seconds)
    s << "  from the first block's load: " << fmt("%.3f", playing_seconds(c, ctx.setup))
      << " s played, " << fmt("%.3f", *o.planned_seconds) << " s in the feed plan (exact stop)\n";
  for (const HoldStop& h : c.hold_stops()) {
    s << "  hold at " << fmt("%.6g", h.pressed / ctx.setup.clock_hz) << " s: at rest "
      << fmt("%.3g", (h.at_rest - h.pressed) / ctx.setup.clock_hz) << " s later at ("
      << fmt("%.3f", (f.start.x + h.position.x) * o.blu_mm) << ", "
      << fmt("%.3f", (f.start.y + h.position.y) * o.blu_mm) << ") mm, ";
    if (h.resumed == UINT64_MAX) s << "never resumed\n";
    else s << "resumed at " << fmt("%.6g", h.resumed / ctx.setup.clock_hz) << " s\n";
  }
  if (c.stopped())
    s << "  " << tape_error_message(static_cast<TapeError>(o.run.last.error_code)) << " at "
      << fmt("%.6g", c.cycles() / ctx.setup.clock_hz) << " s in block N" << o.run.last.error_block
      << ": stopped at (" << fmt("%.3f", (f.start.x + c.position().x) * o.blu_mm) << ", "
      << fmt("%.3f", (f.start.y + c.position().y) * o.blu_mm) << ") mm\n";
  if (c.paused())
    s << "  paused after block N" << o.run.last.block_n << " at "
      << fmt("%.6g", c.cycles() / ctx.setup.clock_hz)
      << " s (M00, or M01 with the optional stop on); no cycle start comes (--events start@Ts)\n";
  if (c.violation_count() == 0) {
    s << (c.stopped()  ? "  every pulse rule holds up to the stop; STOPPED\n"
          : c.paused() ? "  every pulse rule holds up to the pause; PAUSED\n"
                       : "  every pulse rule holds; PASS\n");
  } else {
    std::vector<Violation> sorted = c.violations();
    std::stable_sort(sorted.begin(), sorted.end(),
                     [](const Violation& a, const Violation& b) { return a.cycle < b.cycle; });
    const Violation& v = sorted.front();
    s << "  FAIL: " << c.violation_count() << " violation(s); first: " << rule_name(v.rule);
    if (v.block != SIZE_MAX) s << " in block N" << v.n;
    s << " at cycle " << v.cycle << ": " << v.detail << "\n";
  }
  return s.str();
}

}  // namespace ncinterp::checker
