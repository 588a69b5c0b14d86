// Measurement of L1 (see line_run.h).
#include "line_run.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <type_traits>

#include "line_scheme.h"

namespace ncinterp::sampled {

LineRun run_line(double length, double angle_rad, double h, Arithmetic arith) {
  if (!(length > 0) || !std::isfinite(length)) throw std::invalid_argument("line length must be positive");
  if (!(h > 0) || !(h <= 0.5)) throw std::invalid_argument("h must be in (0, 0.5]");
  const long double ex = length * std::cos(static_cast<long double>(angle_rad));
  const long double ey = length * std::sin(static_cast<long double>(angle_rad));
  const auto periods = static_cast<uint64_t>(std::llround(1.0 / h));
  return with_arithmetic(arith, 2 * length, [&](auto& a) {
    using Scheme = LineScheme<std::decay_t<decltype(a)>>;
    Scheme scheme(ex, ey, static_cast<long double>(h) * length, a);
    scheme.start(typename Scheme::Point{a.from_real(0), a.from_real(0)});
    LineRun run;
    run.quantum = a.quantum();
    run.points.push_back({0, 0});
    for (uint64_t i = 0; i < periods; ++i) {
      const OpCount before = a.ops();
      const auto p = scheme.step();
      run.ops_per_period = a.ops() - before;
      const RealPoint q{a.to_real(p.x), a.to_real(p.y)};
      run.points.push_back(q);
      run.max_deviation =
          std::max(run.max_deviation, static_cast<double>(std::fabs(q.x * ey - q.y * ex) / length));
    }
    const RealPoint last = run.points.back();
    run.endpoint_error = static_cast<double>(std::hypot(last.x - ex, last.y - ey));
    return run;
  });
}

}  // namespace ncinterp::sampled
