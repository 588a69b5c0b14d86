// Measurements of the circle methods (see circle_runs.h).
#include "circle_runs.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include "circle_scheme.h"

namespace ncinterp::sampled {
namespace {

constexpr long double kPi = 3.141592653589793238462643383279502884L;

long double norm(RealPoint p) { return std::sqrt(p.x * p.x + p.y * p.y); }

// Largest distance from the circle of the chord p..q: at an end, or at the chord's point
// nearest the centre when that lies between the ends.
long double chord_error(RealPoint p, RealPoint q, long double r) {
  long double e = std::max(std::fabs(norm(p) - r), std::fabs(norm(q) - r));
  const long double dx = q.x - p.x, dy = q.y - p.y, len2 = dx * dx + dy * dy;
  if (len2 > 0) {
    const long double t = -(p.x * dx + p.y * dy) / len2;
    if (t > 0 && t < 1) e = std::max(e, r - std::fabs(p.x * dy - p.y * dx) / std::sqrt(len2));
  }
  return e;
}

void check_arguments(Method method, double radius, double h) {
  if (method == Method::kL1) throw std::invalid_argument("L1 is a line method");
  if (!(radius > 0) || !std::isfinite(radius)) throw std::invalid_argument("radius must be positive");
  if (!(h > 0) || !(h <= 0.5)) throw std::invalid_argument("h must be in (0, 0.5]");
}

// A run that never sweeps its angle is a bug or a broken scheme, not an endless loop.
uint64_t period_limit(double angle, double h) { return static_cast<uint64_t>(4.0 * angle / h) + 16; }

template <class Arith>
QuarterRun quarter(Method method, double radius, double h, Starter starter, Arith& a) {
  using Scheme = CircleScheme<Arith>;
  Scheme scheme(method, h, starter, a);
  scheme.start(typename Scheme::Point{a.from_real(radius), a.from_real(0)});
  QuarterRun run;
  run.quantum = a.quantum();
  const auto real = [&a](typename Scheme::Point p) { return RealPoint{a.to_real(p.x), a.to_real(p.y)}; };
  run.points.push_back(real(scheme.point()));
  const uint64_t limit = period_limit(kPi / 2, h);
  while (run.points.back().x > 0) {
    if (run.points.size() > limit)
      throw std::runtime_error(std::string(method_name(method)) + " did not sweep a quarter turn");
    const OpCount before = a.ops();
    run.points.push_back(real(scheme.step()));
    run.ops_per_period = a.ops() - before;
  }
  for (size_t i = 0; i < run.points.size(); ++i) {
    const RealPoint p = run.points[i];
    const double e = static_cast<double>(std::fabs(norm(p) - radius));
    if (e > run.max_radial_error || i == 0) {
      run.max_radial_error = e;
      run.worst_angle_deg = static_cast<double>(-std::atan2(p.y, p.x) * 180 / kPi);
    }
    if (i > 0)
      run.max_path_error =
          std::max(run.max_path_error, static_cast<double>(chord_error(run.points[i - 1], p, radius)));
  }
  run.end_error = static_cast<double>(norm(run.points.back()) - radius);
  return run;
}

template <class Arith>
TurnsRun turns(Method method, double radius, double h, int count, Starter starter, Arith& a) {
  using Scheme = CircleScheme<Arith>;
  Scheme scheme(method, h, starter, a);
  scheme.start(typename Scheme::Point{a.from_real(radius), a.from_real(0)});
  TurnsRun run;
  run.max_error_per_turn.assign(1, 0.0);
  const uint64_t limit = period_limit(2 * kPi * count, h);
  long double prev_y = 0;
  while (true) {
    const typename Scheme::Point q = scheme.step();
    const long double x = a.to_real(q.x), y = a.to_real(q.y);
    if (!std::isfinite(x) || !std::isfinite(y))
      throw std::overflow_error(std::string(method_name(method)) + " at h = " + std::to_string(h) +
                                ": the radius outgrew the number range in turn " +
                                std::to_string(run.max_error_per_turn.size()));
    if (++run.periods > limit)
      throw std::runtime_error(std::string(method_name(method)) + " did not complete its turns");
    if (prev_y > 0 && y <= 0 && x > 0) {  // crossed the positive X axis: a turn is complete
      if (static_cast<int>(run.max_error_per_turn.size()) == count) break;
      run.max_error_per_turn.push_back(0.0);
    }
    prev_y = y;
    double& worst = run.max_error_per_turn.back();
    worst = std::max(worst, static_cast<double>(std::fabs(std::sqrt(x * x + y * y) - radius)));
  }
  return run;
}

}  // namespace

QuarterRun run_quarter(Method method, double radius, double h, Starter starter, Arithmetic arith) {
  check_arguments(method, radius, h);
  return with_arithmetic(arith, 2 * radius, [&](auto& a) { return quarter(method, radius, h, starter, a); });
}

TurnsRun run_turns(Method method, double radius, double h, int count, Starter starter, Arithmetic arith) {
  check_arguments(method, radius, h);
  if (count < 2) throw std::invalid_argument("turns must be at least 2");
  return with_arithmetic(arith, 2 * radius, [&](auto& a) { return turns(method, radius, h, count, starter, a); });
}

double TurnsRun::drift_per_turn() const {
  if (max_error_per_turn.size() < 2) return 0.0;
  return (max_error_per_turn.back() - max_error_per_turn.front()) / (max_error_per_turn.size() - 1);
}

double period_angle(Method method, double h) { return method == Method::kK6 ? 2 * h : h; }

double local_step_error(Method method, double h) {
  check_arguments(method, 1.0, h);
  const double theta = period_angle(method, h);
  double worst = 0;
  for (int j = 0; j < 16; ++j) {
    const double phi = 2 * static_cast<double>(kPi) * j / 16;
    FloatArith<double> a;
    CircleScheme<FloatArith<double>> scheme(method, h, Starter::kK7, a);
    // Clockwise: the point a period earlier is at phi + theta, the next at phi - theta.
    scheme.start({std::cos(phi + theta), std::sin(phi + theta)}, {std::cos(phi), std::sin(phi)});
    const auto p = scheme.step();
    worst = std::max(worst, std::hypot(p.x - std::cos(phi - theta), p.y - std::sin(phi - theta)));
  }
  return worst;
}

}  // namespace ncinterp::sampled
