// One check of a tape (see check_session.h).
#include "check_session.h"

#include <chrono>
#include <cmath>
#include <stdexcept>

#include "arc_prepare.h"
#include "feed_plan.h"
#include "chords/chord_planner.h"
#include "frame_source.h"
#include "line_schedule.h"

#ifdef NCINTERP_CHECKER_HAS_RTL
#include "rtl_models.h"
#include "verilated_interp.h"
#endif

namespace ncinterp::checker {
namespace {

// Enough clocks for the whole program: reading every frame plus every block's time (arcs
// get twice their iterations as slack, and their preparation: ArcPrepare::clocks), so a run
// that needs more has hung.
uint64_t cycle_budget(const std::vector<ProgrammedBlock>& blocks, size_t frames,
                      uint64_t cycles_per_frame, const InterpConfig& cfg) {
  uint64_t total = static_cast<uint64_t>(frames) * cycles_per_frame + 10000;
  for (const ProgrammedBlock& b : blocks) {
    const uint64_t big = static_cast<uint64_t>(std::max({std::llabs(b.tape.dx), std::llabs(b.tape.dy),
                                                         std::llabs(b.tape.i), std::llabs(b.tape.j)}));
    const LineSchedule s(big, 0, line_step(b.tape, cfg), cfg.feed_modulus);
    const uint64_t iteration = cfg.serial() ? SerialDda::iteration_clocks(cfg.inc_width) : 1;
    total += std::max(s.duration(), 4 * s.iterations() * iteration + 4) + 4 + cfg.ramp_clocks(4 * s.iterations());
    if (b.is_arc()) total += ArcPrepare::clocks(cfg.inc_width, cfg.serial(), 4 * s.iterations());
  }
  return total + total / 8;
}

}  // namespace

bool rtl_available() {
#ifdef NCINTERP_CHECKER_HAS_RTL
  return true;
#else
  return false;
#endif
}

double blu_of(const tape::Format& format) { return std::pow(10.0, -static_cast<double>(format.frac_digits)); }

void match_first_stage(CheckSetup& s, const firststage::FirstStageOptions& o, firststage::GridPoint start) {
  const bool circle_mode = s.format.circle_mode;  // the machine's, not the tape's
  const bool misc_functions = s.format.misc_functions;
  s.format = firststage::tape_format(o);
  s.format.circle_mode = circle_mode;
  s.format.misc_functions = misc_functions;
  s.tol_mm = o.tol_mm;
  s.start_mm = firststage::Vec2{start.x * o.blu_mm, start.y * o.blu_mm};
  s.cutter_radius_mm = o.cutter_radius_mm;
  s.cutter_left = o.side_left;
}

GridPoint tape_start(const firststage::Contour* contour, const CheckSetup& setup) {
  const double to_blu = 1.0 / blu_of(setup.format);
  firststage::Vec2 s;
  if (setup.start_mm) s = *setup.start_mm;
  else if (contour) s = contour->origin;
  return firststage::round_to_grid(to_blu * s);
}

CheckOutcome run_check(const std::vector<uint8_t>& frames, const firststage::Contour* contour,
                       const CheckSetup& setup) {
  if (!(setup.clock_hz > 0)) throw std::invalid_argument("--clock-hz must be > 0");
  if (!(setup.reader_cps > 0)) throw std::invalid_argument("--reader-cps must be > 0");
  if (!(setup.tol_mm > 0)) throw std::invalid_argument("--tol must be > 0");
  // The cutter-centre path starts R off the contour, where only the first stage knows.
  if (setup.cutter_radius_mm > 0 && contour && !setup.start_mm)
    throw std::invalid_argument(
        "--cutter-radius needs --start X,Y: the cutter path's start, start_mm in the report of `ncinterp tape`");
  if (setup.fault && setup.engine != EngineKind::kGolden)
    throw std::invalid_argument("faults are injected through the golden model's test hook only");
  if (setup.engine == EngineKind::kRtl && !rtl_available())
    throw std::invalid_argument("this build has no verilated RTL (use --engine golden)");

  CheckOutcome out;
  out.blu_mm = blu_of(setup.format);
  out.tol_blu = setup.tol_mm / out.blu_mm;
  out.program = tape::parse_frames(frames, setup.format);
  std::vector<ProgrammedBlock> blocks = lay_out(out.program);

  InterpConfig cfg = interp_config(setup.clock_hz, setup.format, setup.rapid_mm_min, setup.accel_mm_s2);
  cfg.pos_width = setup.pos_width;
  cfg.arch = setup.arch;
  if (contour) {
    ReferenceOptions ro;
    ro.blu_mm = out.blu_mm;
    ro.start = tape_start(contour, setup);
    ro.cutter_radius_mm = setup.cutter_radius_mm;
    ro.cutter_left = setup.cutter_left;
    out.reference = std::make_unique<ReferenceContour>(*contour, ro);
  }
  CheckerOptions co;
  co.feed_modulus = cfg.feed_modulus;
  co.schedule = setup.schedule;
  co.inc_width = cfg.inc_width;
  co.lead_bits = SerialDda::player_lead_bits(cfg);
  co.rapid_step = cfg.rapid_step_on_port();
  co.accel_step = cfg.accel_step;
  co.operator_holds = !setup.events.empty();
  for (const OperatorEvent& e : setup.events)
    if (e.kind == OperatorEvent::kFeedOverride) co.max_override = std::max<uint32_t>(co.max_override, e.value);
  // The held stretches: each hold press to the next start press. Settling: a ramp down from
  // the cap (M / 2 / du clocks) and a serial iteration in flight.
  for (size_t k = 0; k < setup.events.size(); ++k) {
    if (setup.events[k].kind != OperatorEvent::kHold) continue;
    uint64_t start = UINT64_MAX;
    for (size_t e = k + 1; e < setup.events.size(); ++e)
      if (setup.events[e].kind == OperatorEvent::kStart) {
        start = setup.events[e].cycle;
        break;
      }
    co.holds.emplace_back(setup.events[k].cycle, start);
  }
  if (const OperatorEvent* stop = first_stop(setup.events)) {
    co.stop_cycle = stop->cycle;
    co.stop_code = static_cast<uint8_t>(stop_error(stop->kind));
  }
  // Settling: the ramp down from the fastest rate a block of the tape asks (S, an arc's
  // F 2^(k+1) as its N < 2^(k+1), times the largest feed override), and a serial iteration
  // in flight.
  unsigned __int128 fastest = 0;
  for (const ProgrammedBlock& b : blocks) {
    const uint64_t big = static_cast<uint64_t>(std::max({std::llabs(b.tape.dx) + std::llabs(b.tape.i),
                                                         std::llabs(b.tape.dy) + std::llabs(b.tape.j)}));
    fastest = std::max(fastest, b.is_arc() ? static_cast<unsigned __int128>(b.tape.feed) << (bit_length(big) + 1)
                                           : line_step(b.tape, cfg));
  }
  const uint64_t cap = (cfg.feed_modulus - 1) >> 1;
  fastest = fastest * co.max_override / kOverrideOne;
  const uint64_t top = fastest < cap ? static_cast<uint64_t>(fastest) : cap;
  co.hold_settle = (cfg.accel_step ? top / cfg.accel_step : 0) + 2 +
                   (cfg.serial() ? 2 * SerialDda::iteration_clocks(cfg.inc_width) : 1);
  co.arc_bound_blu = setup.arc_bound_blu;
  co.keep_pulses = setup.keep_pulses;
  const uint64_t cpf = FrameSource::cycles_per_frame_for(setup.clock_hz, setup.reader_cps);
  const uint64_t budget =
      setup.max_cycles ? setup.max_cycles
                       : cycle_budget(blocks, frames.size(), cpf, cfg) + last_event_cycle(setup.events);
  out.checker = std::make_unique<TrajectoryChecker>(std::move(blocks), out.reference.get(), co);

  TrajectoryChecker& checker = *out.checker;
  const auto& progress = setup.progress;
  constexpr uint64_t kProgressEvery = uint64_t{1} << 22;
  uint64_t next_progress = 0;
  auto observe = [&checker, &progress, &next_progress, budget](uint64_t cycle, const InterpOutputs& o) {
    checker.observe(cycle, o);
    if (cycle >= next_progress && progress) {
      progress(cycle, budget);
      next_progress = (cycle / kProgressEvery + 1) * kProgressEvery;
    }
  };
  FrameSource source(frames, cpf, setup.events);
  // A run that a stop ended is watched on for pulses the stop should have muted.
  auto watch_past_stop = [&](auto& dut, const RunEnd& end) {
    if (end.last.error && is_stop_error(end.last.error_code))
      run_past_stop(dut, source, end.cycles, SerialDda::stop_watch_clocks(cfg.inc_width),
                    [&checker](uint64_t c, const InterpOutputs& o) { checker.observe_after_stop(c, o); });
    return end;
  };
  const auto t0 = std::chrono::steady_clock::now();
  if (setup.engine == EngineKind::kGolden) {
    GoldenInterp dut(cfg);
    if (setup.fault) dut.inject(*setup.fault);
    out.run = watch_past_stop(dut, setup.every_clock ? run_engine(dut, source, budget, observe)
                                                     : run_engine_jumping(dut, source, budget, checker, observe));
  } else {
#ifdef NCINTERP_CHECKER_HAS_RTL
    out.run = with_rtl_model(cfg.arch, [&](auto model) {
      VerilatedInterp<typename decltype(model)::type> dut(cfg, rtl_built_config(cfg.arch));
      return watch_past_stop(dut, run_engine(dut, source, budget, observe));
    });
#endif
  }
  out.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  checker.finish(out.run.last);
  if (out.reference) checker.check_tolerance(out.tol_blu);
  if (setup.accel_mm_s2 > 0 && setup.events.empty()) {
    FeedPlanOptions plan;
    plan.accel_mm_s2 = setup.accel_mm_s2;
    plan.lookaheads.clear();
    out.planned_seconds = plan_feed(out.program, cfg, setup.clock_hz, plan).exact_stop_s;
  }
  return out;
}

}  // namespace ncinterp::checker
