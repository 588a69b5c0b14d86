// The sweep over methods, radii and h (see method_study.h).
#include "method_study.h"

#include <algorithm>
#include <cmath>
#include <iterator>
#include <stdexcept>

#include "circle_runs.h"
#include "line_run.h"
#include "paper_claims.h"

namespace ncinterp::sampled {
namespace {

constexpr double kPi = 3.14159265358979323846;

// Whether a double result is decided by round-off: it moves by more than 1% when the same
// run is repeated in long double.
bool roundoff_limited(double in_double, double in_long_double) {
  return !(std::fabs(in_double - in_long_double) <= 0.01 * std::fabs(in_long_double));
}

StudyRow line_row(double radius, double h, const StudyConfig& cfg) {
  const double angle = kLineAngleDeg * kPi / 180;
  const LineRun d = run_line(radius, angle, h, Arithmetic::double_precision());
  const LineRun ld = run_line(radius, angle, h, Arithmetic::long_double_precision());
  const LineRun fx = run_line(radius, angle, h, Arithmetic::fixed(cfg.word_bits));
  StudyRow row;
  row.method = Method::kL1;
  row.radius = radius;
  row.h = h;
  row.periods = d.points.size() - 1;
  row.error = row.path_error = d.max_deviation;  // a chord between points on a line stays on it
  row.end_error = d.endpoint_error;
  row.fixed_error = fx.max_deviation;
  row.fixed_minus_double = max_distance(fx.points, d.points);
  row.quantum = fx.quantum;
  row.roundoff_limited = roundoff_limited(d.max_deviation, ld.max_deviation);
  row.ops_per_period = d.ops_per_period;
  return row;
}

StudyRow circle_row(Method m, double radius, double h, const StudyConfig& cfg) {
  const QuarterRun d = run_quarter(m, radius, h, cfg.starter, Arithmetic::double_precision());
  const QuarterRun ld = run_quarter(m, radius, h, cfg.starter, Arithmetic::long_double_precision());
  const QuarterRun fx = run_quarter(m, radius, h, cfg.starter, Arithmetic::fixed(cfg.word_bits));
  const TurnsRun td = run_turns(m, radius, h, cfg.turns, cfg.starter, Arithmetic::double_precision());
  const TurnsRun tld = run_turns(m, radius, h, cfg.turns, cfg.starter, Arithmetic::long_double_precision());
  StudyRow row;
  row.method = m;
  row.radius = radius;
  row.h = h;
  row.periods = d.points.size() - 1;
  row.error = d.max_radial_error;
  row.path_error = d.max_path_error;
  row.end_error = d.end_error;
  row.worst_angle_deg = d.worst_angle_deg;
  row.first_turn_error = td.max_error_per_turn.front();
  row.last_turn_error = td.max_error_per_turn.back();
  row.drift_per_turn = td.drift_per_turn();
  row.drifts = row.last_turn_error > 1.1 * row.first_turn_error &&
               !roundoff_limited(td.drift_per_turn(), tld.drift_per_turn());
  row.local_error = local_step_error(m, h);
  row.fixed_error = fx.max_radial_error;
  row.fixed_minus_double = max_distance(fx.points, d.points);
  row.quantum = fx.quantum;
  if (const PaperClaim* claim = quarter_claim(m)) row.paper_error = claim->value(h, radius);
  row.roundoff_limited = roundoff_limited(d.max_radial_error, ld.max_radial_error);
  row.ops_per_period = d.ops_per_period;
  return row;
}

MethodSummary summarise(Method m, const std::vector<StudyRow>& rows) {
  MethodSummary s;
  s.method = m;
  std::vector<double> eh, e, lh, l, dh, dr;
  for (const StudyRow& r : rows) {
    if (r.method != m) continue;
    ++s.rows;
    s.ops_per_period = r.ops_per_period;
    if (r.roundoff_limited) {
      ++s.roundoff_rows;
    } else if (r.error > 0) {
      eh.push_back(r.h);
      e.push_back(r.error / r.radius);
    }
    if (r.local_error > 0) {
      lh.push_back(r.h);
      l.push_back(r.local_error);
    }
    if (r.drifts) {
      ++s.drifting_rows;
      dh.push_back(r.h);
      dr.push_back(r.drift_per_turn / r.radius);
    }
  }
  s.error = fit_order(eh, e);
  s.local = fit_order(lh, l);
  s.drift = fit_order(dh, dr);
  return s;
}

}  // namespace

std::vector<double> default_h_sweep() {
  std::vector<double> hs;
  for (int i = 0; i <= 12; ++i) hs.push_back(std::pow(10.0, -4.0 + i / 4.0));
  return hs;
}

std::vector<double> default_radii_mm() { return {1.0, 10.0, 100.0}; }

Study run_study(const StudyConfig& config) {
  if (config.radii_mm.empty() || config.hs.empty()) throw std::invalid_argument("no radius or no h to study");
  if (config.turns < 2) throw std::invalid_argument("--turns must be at least 2 (drift compares the first and last turn)");
  Study study;
  study.config = config;
  const size_t total = std::size(kAllMethods) * config.radii_mm.size() * config.hs.size();
  for (Method m : kAllMethods)
    for (double radius : config.radii_mm)
      for (double h : config.hs) {
        study.rows.push_back(m == Method::kL1 ? line_row(radius, h, config) : circle_row(m, radius, h, config));
        if (config.progress) config.progress(study.rows.size(), total);
      }
  for (Method m : kAllMethods) study.summaries.push_back(summarise(m, study.rows));
  return study;
}

}  // namespace ncinterp::sampled
