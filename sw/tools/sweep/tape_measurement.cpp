// First stage + golden model + checker at one width (see tape_measurement.h).
#include "tape_measurement.h"

#include "atomic_file.h"
#include "check_report.h"
#include "check_session.h"

namespace ncinterp::sweep {

WidthTape tape_at_width(const SweepInput& input, unsigned width, const MeasureSetup& setup) {
  firststage::FirstStageOptions o = setup.first_stage;
  o.width = width;
  const firststage::FirstStageResult fs = firststage::run_first_stage(input.contour, o);
  WidthTape t;
  t.start = fs.start;
  t.program = firststage::make_program(fs, o);
  t.format = firststage::tape_format(o);
  t.frames = tape::add_parity(tape::format_program(t.program, t.format));
  return t;
}

InputResult measure_input(const SweepInput& input, unsigned width, const MeasureSetup& setup,
                          const std::string& tape_path) {
  InputResult r;
  r.input = input.path;
  WidthTape tape;
  try {
    tape = tape_at_width(input, width, setup);
    r.blocks = tape.program.blocks.size();
    r.frames = tape.frames.size();
  } catch (const std::exception& e) {
    r.failure = std::string("first stage: ") + e.what();
    return r;
  }

  checker::CheckSetup cs;
  firststage::FirstStageOptions o = setup.first_stage;
  o.width = width;
  checker::match_first_stage(cs, o, tape.start);
  cs.clock_hz = setup.clock_hz;
  cs.reader_cps = setup.reader_cps;
  cs.pos_width = setup.pos_width;
  cs.arch = setup.arch;
  cs.format.circle_mode = setup.circle_mode;
  cs.engine = EngineKind::kGolden;
  cs.keep_pulses = false;
  try {
    const checker::CheckOutcome out = checker::run_check(tape.frames, &input.contour, cs);
    const checker::TrajectoryChecker& c = *out.checker;
    r.path_error_max_blu = c.path_error().max;
    r.total_error_max_mm = c.total_error().max * out.blu_mm;
    r.violations = c.violation_count();
    if (!c.violations().empty()) {
      const checker::Violation& v = c.violations().front();
      r.first_violation = std::string(checker::rule_name(v.rule)) + " at block N" + std::to_string(v.n) + ": " + v.detail;
    }
    const checker::FeedSummary feed = checker::feed_summary(c);
    r.feed_error_worst = feed.worst_relative_error;
    r.saturated_blocks = feed.saturated;
    r.cycles = out.run.cycles;
  } catch (const std::exception& e) {
    r.failure = std::string("check: ") + e.what();
    return r;
  }
  if (!tape_path.empty()) {
    try {
      write_file_atomically(tape_path, tape.frames);
      r.tape_path = tape_path;
    } catch (const std::exception&) {
      // No tape file: the RTL variant says it has nothing to play for this input.
    }
  }
  return r;
}

}  // namespace ncinterp::sweep
