// What `ncinterp methods` prints and writes: the CSV of every measured row, and the text
// tables (measured errors beside the paper's, fitted laws, the paper's claims checked, the
// comparison with the hardware DDA).
// Idea: everything shown is formatted from the measurements; agreement with a claim is
// decided by fixed tolerances stated beside the table, never by hand.
#pragma once
#include <string>
#include <vector>

#include "dda_comparison.h"
#include "method_study.h"

namespace ncinterp::sampled {

// One line per study row; the first column is the method (L1, K1..K7); every other column
// is numeric (empty where it does not apply to the method).
std::string methods_csv(const Study& study);

std::string methods_text(const Study& study, const std::vector<ComparisonRow>& comparison, double blu_mm);

// Tolerances for "agrees": fitted order within this of the claimed one, and fitted
// constant within this fraction of the claimed one.
constexpr double kOrderTolerance = 0.1;
constexpr double kConstantTolerance = 0.1;

}  // namespace ncinterp::sampled
