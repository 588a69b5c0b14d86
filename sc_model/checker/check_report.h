// Reports of a check: the JSON report (`ncinterp check --report`) and the short text
// summary printed on stdout.
// Idea: every figure is given in mm in the part's own coordinates (tape start + counted
// position), with the block N, the clock and the position where it happens; the BLU
// values are kept beside them because the bounds are stated in BLU.
#pragma once
#include <nlohmann/json.hpp>
#include <string>

#include "check_session.h"

namespace ncinterp::checker {

struct ReportContext {
  std::string tape_file;
  std::string contour_file;  // empty: no contour
  CheckSetup setup;
};

// Worst block time against 1/F (non-saturated blocks), and how many blocks saturate.
struct FeedSummary {
  double worst_relative_error = 0.0;  // (measured - 1/F) / (1/F)
  size_t worst_block = SIZE_MAX;
  size_t saturated = 0;
  size_t measured = 0;
};
FeedSummary feed_summary(const TrajectoryChecker& checker);

// With the feed ramp: its limit, each axis's largest acceleration of the ramp measured
// (mm/s^2), the largest measured/(limit + allowance) (<= 1: the rule holds), and the
// largest centripetal acceleration v^2 / R measured on an arc (mm/s^2).
struct AccelSummary {
  double limit_mm_s2 = 0.0;
  double max_mm_s2[2] = {0.0, 0.0};
  double worst_ratio = 0.0;
  double max_centripetal_mm_s2 = 0.0;
};
AccelSummary accel_summary(const TrajectoryChecker& checker, const CheckSetup& setup, double blu_mm);

nlohmann::json check_report_json(const CheckOutcome& outcome, const ReportContext& context);
std::string check_summary_text(const CheckOutcome& outcome, const ReportContext& context);

}  // namespace ncinterp::checker
