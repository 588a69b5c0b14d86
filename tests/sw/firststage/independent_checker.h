// Test-side deviation checker, independent of the first stage's chord code: the true curve
// is given as a dense polyline made by the test (from the analytic formula where there is
// one), the tape path as points in mm. Two measures, each by brute force over a window
// that follows both sequences in order:
//  - normal: for every interior curve sample, the distance along its normal (from the
//    neighbouring samples) to where the normal meets the path (Kolesnikov's measure);
//  - path: for points every `step` along the path, the Euclidean distance to the curve
//    polyline.
#pragma once
#include <vector>

namespace ncinterp::test {

struct P2 {
  double x = 0, y = 0;
};

struct CheckResult {
  double normal_max = 0.0;  // max over curve samples of the normal distance to the path
  double path_max = 0.0;    // max over path samples of the distance to the curve
  long unmatched = 0;       // curve samples whose normal met no path segment nearby
};

CheckResult check_path(const std::vector<P2>& curve, const std::vector<P2>& path, double step);

}  // namespace ncinterp::test
