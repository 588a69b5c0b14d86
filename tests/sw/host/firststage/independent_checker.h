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
// measured again exactly, over the whole other polyline. The result is the brute-force
// result, in time about linear in the number of samples.
#pragma once
#include <limits>
#include <vector>

namespace ncinterp::test {

struct P2 {
  double x = 0, y = 0;
};

struct CheckResult {
  double normal_max = 0.0;  // max over curve samples of the normal distance to the path
  double path_max = 0.0;    // max over path samples of the distance to the curve
  long unmatched = 0;       // curve samples (outside corner zones) whose normal meets no path segment
  long corner_samples = 0;  // curve samples in corner zones (measured by Euclidean distance)
  P2 normal_worst, path_worst;  // where each maximum was found (for failure messages)
  long samples = 0;         // curve + path samples measured
  long wide_searches = 0;   // samples that needed the wide window
};

// `corners`: points of the curve where its tangent jumps (its two ends count as corners
// too). The normal is undefined there, and the path's vertex there is the corner rounded
// to the grid, so it may lie a little beyond or before it; a normal near the corner then
// passes beside that vertex and meets a neighbouring chord far away, or nothing. Curve
// samples closer to a corner than the path's nearest vertex is (plus one sample spacing)
// are therefore measured by their Euclidean distance to the path instead.
// `exact_above` (mm): estimates at or below it are not measured again, so a maximum at
// or below it may be an upper bound of the true one (never smaller than it); a maximum
// above it is exact. A test of "max <= bound" passes exact_above = bound and is decided
// exactly, without the exact searches a slowly growing deviation would cost (each sample
// a new maximum). 0: every maximum exact.
CheckResult check_path(const std::vector<P2>& curve, const std::vector<P2>& path, double step,
                       const std::vector<P2>& corners = {}, double exact_above = 0.0);

// Min and max over `points` of the Euclidean distance to the nearest of the polylines
// `lines` (exact). The cutter-offset tests use it: every contour point must be between
// R - delta and R + delta from the cutter-centre path, every path point at least R - delta
// from the contour (no gouge).
struct DistanceRange {
  double min = std::numeric_limits<double>::infinity();
  double max = 0.0;
  P2 at_min, at_max;
};
DistanceRange distance_range(const std::vector<P2>& points, const std::vector<std::vector<P2>>& lines);

}  // namespace ncinterp::test
