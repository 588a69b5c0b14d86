// Aggregates of a sweep row over its inputs (see sweep_row.h).
#include "sweep_row.h"

#include <cmath>
#include <filesystem>

namespace ncinterp::sweep {

std::string SweepRow::missing_input() const {
  for (const InputResult& in : inputs)
    if (!in.measured()) return std::filesystem::path(in.input).filename().string() + ": " + in.failure;
  return inputs.empty() ? "no input" : "";
}

std::optional<uint64_t> SweepRow::total(uint64_t InputResult::*field) const {
  if (!missing_input().empty()) return std::nullopt;
  uint64_t sum = 0;
  for (const InputResult& in : inputs) sum += in.*field;
  return sum;
}

std::optional<double> SweepRow::worst(double InputResult::*field) const {
  if (!missing_input().empty()) return std::nullopt;
  double w = 0.0;
  for (const InputResult& in : inputs)
    if (std::fabs(in.*field) > std::fabs(w)) w = in.*field;
  return w;
}

}  // namespace ncinterp::sweep
