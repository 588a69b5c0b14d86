// End-to-end regression support: contour -> first stage -> tape (in memory) -> engine ->
// trajectory checker, with the same code paths as `ncinterp tape` and `ncinterp check`.
#pragma once
#include <string>
#include <vector>

#include "check_session.h"
#include "firststage.h"
#include "inputs/contour_inputs.h"

namespace ncinterp::regression {

struct Case {
  std::string name;
  firststage::Contour contour;
  firststage::FirstStageOptions first_stage;
  checker::CheckSetup check;  // tol, format and start are filled from first_stage
};

// The first stage's tape for the case, as frames with parity (what `ncinterp tape` writes).
std::vector<uint8_t> make_tape(const Case& c, firststage::GridPoint* start = nullptr);
// Makes the tape and checks it on the case's engine.
checker::CheckOutcome run_case(const Case& c);
// One line: "name: PASS total max ... path max ... (cycles, s)" or the first violation.
std::string describe(const Case& c, const checker::CheckOutcome& out);

std::string example_path(const std::string& name);  // examples/contours/<name>

}  // namespace ncinterp::regression
