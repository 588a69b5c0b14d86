// End-to-end regression support (see regression_support.h).
#include "regression_support.h"

#include <cstdio>

#include "check_report.h"
#include "tape/tape.h"

namespace ncinterp::regression {

std::string example_path(const std::string& name) {
  return std::string(NCINTERP_EXAMPLES_DIR) + "/" + name;
}

std::vector<uint8_t> make_tape(const Case& c, firststage::GridPoint* start) {
  const firststage::FirstStageResult r = firststage::run_first_stage(c.contour, c.first_stage);
  if (start) *start = r.start;
  const tape::Program p = firststage::make_program(r, c.first_stage);
  return tape::add_parity(tape::format_program(p, firststage::tape_format(c.first_stage)));
}

checker::CheckOutcome run_case(const Case& c) {
  firststage::GridPoint start;
  const std::vector<uint8_t> frames = make_tape(c, &start);
  checker::CheckSetup s = c.check;
  checker::match_first_stage(s, c.first_stage, start);
  return checker::run_check(frames, &c.contour, s);
}

std::string describe(const Case& c, const checker::CheckOutcome& out) {
  checker::ReportContext ctx;
  ctx.tape_file = c.name;
  ctx.setup = c.check;
  ctx.setup.tol_mm = c.first_stage.tol_mm;
  ctx.setup.cutter_radius_mm = c.first_stage.cutter_radius_mm;
  return checker::check_summary_text(out, ctx);
}

}  // namespace ncinterp::regression
