// Sampled-data methods against the hardware circle DDA (see dda_comparison.h).
#include "dda_comparison.h"

#include "bit_length.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include "arc_geometry.h"
#include "dda_circle.h"
#include "circle_runs.h"

namespace ncinterp::sampled {
namespace {

constexpr double kDoubleBudgetBlu = 0.5;  // the method's own error, in double
constexpr double kTotalBudgetBlu = 1.0;   // with the word's rounding
constexpr double kSmallestH = 1e-6;
constexpr int kLongestWord = 62;

}  // namespace

double DdaQuadrant::additions_per_iteration() const {
  return iterations == 0 ? 0.0 : 2.0 + 2.0 * static_cast<double>(pulses) / static_cast<double>(iterations);
}

DdaQuadrant run_hardware_dda_quadrant(int64_t radius_blu) {
  const unsigned width = std::max(2u, bit_length(static_cast<uint64_t>(radius_blu)));
  const ArcWords words = ArcWords::from_signed(-radius_blu, -radius_blu, -radius_blu, 0, /*ccw=*/false);
  if (radius_blu < 1 || width > 31 || check_arc(words, width) != TapeError::kNone)
    throw std::invalid_argument("hardware DDA: radius " + std::to_string(radius_blu) + " BLU is not a good arc");
  const ArcGeometry g = arc_geometry(words, width);
  CircleDda dda;
  dda.load(g, !words.dx_neg, !words.dy_neg);
  DdaQuadrant q;
  q.radius_blu = radius_blu;
  q.k = g.k;
  int64_t x = radius_blu, y = 0;
  const uint64_t limit = uint64_t{4} << g.k;  // a quadrant takes < 2^(k+1) iterations (docs/circle-dda.md 3.3)
  while (!dda.done()) {
    if (++q.iterations > limit) throw std::runtime_error("hardware DDA did not finish the quadrant");
    const CircleDda::Steps s = dda.iterate();
    if (s.x) x += dda.dir(0) ? 1 : -1;
    if (s.y) y += dda.dir(1) ? 1 : -1;
    if (!s.x && !s.y) continue;
    q.pulses += s.x + s.y;
    const double e = std::fabs(std::hypot(static_cast<double>(x), static_cast<double>(y)) - radius_blu);
    q.max_radial_error_blu = std::max(q.max_radial_error_blu, e);
  }
  return q;
}

SampledForOneBlu sampled_for_one_blu(Method method, int64_t radius_blu, Starter starter) {
  SampledForOneBlu s;
  s.method = method;
  const double r = static_cast<double>(radius_blu);
  // The largest h on the grid within the double budget; give up when halving h (4 grid
  // steps) no longer lowers the error by 10%: the error does not fall with h.
  std::vector<double> errors;
  for (int j = 0;; ++j) {
    const double h = 0.1 * std::pow(2.0, -j / 4.0);
    if (h < kSmallestH) return s;
    const QuarterRun run = run_quarter(method, r, h, starter, Arithmetic::double_precision());
    errors.push_back(run.max_path_error);
    if (run.max_path_error <= kDoubleBudgetBlu) {
      s.reached = true;
      s.h = h;
      s.periods = run.points.size() - 1;
      s.path_error_double_blu = run.max_path_error;
      s.ops_per_period = run.ops_per_period;
      break;
    }
    if (j >= 4 && errors[j] > 0.9 * errors[j - 4]) return s;
  }
  // The shortest word: from the first whose quantum is at most 1 BLU.
  for (int bits = bit_length(static_cast<uint64_t>(2 * radius_blu)) + 1; bits <= kLongestWord; ++bits) {
    try {
      const QuarterRun run = run_quarter(method, r, s.h, starter, Arithmetic::fixed(bits));
      if (run.max_path_error <= kTotalBudgetBlu) {
        s.word_bits = bits;
        s.path_error_fixed_blu = run.max_path_error;
        break;
      }
    } catch (const std::overflow_error&) {
      // this word is too short for the run: try a longer one
    }
  }
  return s;
}

std::vector<ComparisonRow> compare_with_hardware_dda(const std::vector<int64_t>& radii_blu, Starter starter) {
  std::vector<ComparisonRow> rows;
  for (int64_t r : radii_blu) {
    ComparisonRow row;
    row.radius_blu = r;
    row.dda = run_hardware_dda_quadrant(r);
    for (Method m : kCircleMethods) row.methods.push_back(sampled_for_one_blu(m, r, starter));
    rows.push_back(row);
  }
  return rows;
}

}  // namespace ncinterp::sampled
