// Test-side deviation checker, independent of the first stage's chord code: the true curve
// is given as a dense polyline made by the test (from the analytic formula where there is
// one), the tape path as points in mm. Two measures, both following the two sequences in
// order:
//  - normal: for every interior curve sample, the distance along its normal (from the
//    neighbouring samples) to where the normal meets the path (Kolesnikov's measure);
//  - path: for points every `step` along the path, the Euclidean distance to the curve
//    polyline.
// Speed without blind spots: each sample is first measured against a few path segments
// (curve segments) near a pointer that moves along with it. A minimum over fewer
// candidates can only be larger than the true one, so such an estimate that stays at or
// below the running maximum cannot change the result; only an estimate above it is
// measured again over a wide window (the old brute force). The result is the brute-force
// result, in time linear in the number of samples.
#pragma once
#include <vector>

namespace ncinterp::test {

struct P2 {
  double x = 0, y = 0;
};

struct CheckResult {
  double normal_max = 0.0;  // max over curve samples of the normal distance to the path
  double path_max = 0.0;    // max over path samples of the distance to the curve
  // Curve samples whose normal meets no path segment. Near the ends of an open curve the
  // path ends on the end point rounded to the grid, so a normal there may pass beside the
  // path's end: such samples (closer to a curve end than the path's own end is, plus one
  // sample spacing) are measured by their distance to the path's end instead and not
  // counted here.
  long unmatched = 0;
  long samples = 0;         // curve + path samples measured
  long wide_searches = 0;   // samples that needed the wide window
};

CheckResult check_path(const std::vector<P2>& curve, const std::vector<P2>& path, double step);

}  // namespace ncinterp::test
