// The feed plan of a tape (see feed_plan.h).
#include "feed_plan.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "arc_geometry.h"
#include "bit_length.h"
#include "dda_circle.h"
#include "dda_serial.h"

namespace ncinterp::checker {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

uint64_t magnitude(int64_t v) { return static_cast<uint64_t>(v < 0 ? -v : v); }

// One block as continuous mode plans it: its path length, rate, acceleration along the
// path and directions at its ends (unit vectors).
struct PathBlock {
  double length_mm = 0;
  double cruise_mm_s = 0;  // its programmed rate (capped), arcs also below sqrt(A R)
  double accel_mm_s2 = 0;  // the ramp's acceleration along this block's path
  double time_s = 0;       // a block without length: its clocks at the rate
  double start_dir[2] = {0, 0}, end_dir[2] = {0, 0};
  bool stops_after = false;  // M00, M01 or M05: the axes rest after it
  bool stops_before = false; // M03: the axes rest before it
};

void unit(double x, double y, double out[2]) {
  const double n = std::hypot(x, y);
  out[0] = n > 0 ? x / n : 0;
  out[1] = n > 0 ? y / n : 0;
}

// An arc's tangent where its radius vector (from the centre) is (rx, ry).
void tangent(double rx, double ry, bool ccw, double out[2]) {
  if (ccw) unit(-ry, rx, out);
  else unit(ry, -rx, out);
}

// The junction speed of grbl's and Klipper's rule: the speed at which a circle of
// deviation `deviation` tangent to both directions is taken at acceleration `accel`; 0 at
// a reversal, unlimited straight on.
double junction_limit(const double in[2], const double out[2], double accel, double deviation) {
  const double cos_theta = -(in[0] * out[0] + in[1] * out[1]);
  if (cos_theta > 0.999999) return 0;
  if (cos_theta < -0.999999) return kInf;
  const double sin_half = std::sqrt(0.5 * (1 - cos_theta));
  return std::sqrt(accel * deviation * sin_half / (1 - sin_half));
}

// Seconds to cover `length` from speed v0 to v1, cruising at most at vc, accelerating and
// braking at a (|v1^2 - v0^2| <= 2 a length, which the passes ensure).
double block_seconds(double length, double v0, double v1, double vc, double a) {
  const double accel_d = (vc * vc - v0 * v0) / (2 * a), brake_d = (vc * vc - v1 * v1) / (2 * a);
  if (accel_d + brake_d <= length) return (vc - v0) / a + (vc - v1) / a + (length - accel_d - brake_d) / vc;
  const double peak = std::sqrt(std::max(0.0, (2 * a * length + v0 * v0 + v1 * v1) / 2));
  return (peak - v0) / a + (peak - v1) / a;
}

// Continuous mode's time with `lookahead` blocks read beyond the one playing (0: all).
double continuous_seconds(const std::vector<PathBlock>& p, const std::vector<double>& junction,
                          unsigned lookahead) {
  const size_t n = p.size();
  // exit_limit[i]: the fastest block i may leave at and still stop by the end of the last
  // block read: a backward pass from rest over the window.
  std::vector<double> exit_limit(n, 0);
  const auto entry_limit = [&](size_t b, double exit) {  // block b's entry, given its exit
    return std::min(junction[b - 1], std::sqrt(exit * exit + 2 * p[b].accel_mm_s2 * p[b].length_mm));
  };
  if (lookahead == 0) {
    double w = 0;
    for (size_t b = n; b-- > 1;) {
      w = entry_limit(b, w);
      exit_limit[b - 1] = w;
    }
  } else {
    for (size_t i = 0; i + 1 < n; ++i) {
      double w = 0;
      for (size_t b = std::min(n - 1, i + lookahead); b > i; --b) w = entry_limit(b, w);
      exit_limit[i] = w;
    }
  }
  double seconds = 0, entry = 0;
  for (size_t i = 0; i < n; ++i) {
    const PathBlock& b = p[i];
    if (b.length_mm <= 0) {
      seconds += b.time_s;
      entry = 0;
      continue;
    }
    const double exit = std::min(exit_limit[i], std::sqrt(entry * entry + 2 * b.accel_mm_s2 * b.length_mm));
    seconds += block_seconds(b.length_mm, entry, exit, b.cruise_mm_s, b.accel_mm_s2);
    entry = exit;
  }
  return seconds;
}

}  // namespace

uint64_t block_iterations(const tape::Block& b, const InterpConfig& cfg) {
  if (!tape::is_arc(b.motion)) return uint64_t{1} << bit_length(magnitude(b.dx) | magnitude(b.dy));
  const ArcGeometry g =
      arc_geometry(ArcWords::from_signed(b.dx, b.dy, b.i, b.j, b.motion == tape::Motion::kArcCcw), cfg.inc_width);
  CircleDda dda;
  dda.load(g, false, false);
  return dda.iterations_left();
}

FeedPlan plan_feed(const tape::Program& program, const InterpConfig& config, double clock_hz,
                   const FeedPlanOptions& o) {
  InterpConfig cfg = config;
  cfg.accel_step = ramp_step(o.accel_mm_s2, clock_hz, cfg);
  const double m = static_cast<double>(cfg.feed_modulus), du = static_cast<double>(cfg.accel_step);
  const unsigned lead_bits = SerialDda::player_lead_bits(cfg);
  const double cap = static_cast<double>((cfg.feed_modulus - 1) >> std::max(lead_bits, 1u));
  const double fastest = static_cast<double>(cfg.feed_modulus >> lead_bits);  // unramped
  const double blu_mm = std::pow(10.0, -static_cast<double>(cfg.frac_digits));
  const double ramp_accel = du / m * clock_hz * clock_hz;  // iterations per s^2

  FeedPlan plan;
  plan.blocks = program.blocks.size();
  std::vector<PathBlock> path;
  path.reserve(program.blocks.size());
  for (const tape::Block& b : program.blocks) {
    const double n = static_cast<double>(block_iterations(b, cfg));
    const double step = tape::is_arc(b.motion) ? static_cast<double>(b.feed) * n
                                               : static_cast<double>(line_step(b, cfg));
    const double phase = n * m;  // clocks times rate: a block adds N M of phase
    plan.programmed_s += phase / std::min(step, fastest) / clock_hz;
    const double r = std::min(step, cap);
    plan.exact_stop_s +=
        (phase >= r * r / du ? phase / r + r / du : 2 * std::sqrt(phase / du)) / clock_hz;

    PathBlock p;
    p.time_s = phase / r / clock_hz;
    p.stops_after = b.stop || b.optional_stop || b.tool_off;
    p.stops_before = b.tool_on;
    if (tape::is_arc(b.motion)) {
      const bool ccw = b.motion == tape::Motion::kArcCcw;
      const double sx = -static_cast<double>(b.i), sy = -static_cast<double>(b.j);
      const double ex = static_cast<double>(b.dx - b.i), ey = static_cast<double>(b.dy - b.j);
      const double radius = std::hypot(sx, sy) * blu_mm;
      double sweep = std::atan2(sx * ey - sy * ex, sx * ex + sy * ey);  // signed, (-pi, pi]
      if (ccw && sweep < 0) sweep += 2 * M_PI;
      if (!ccw && sweep > 0) sweep -= 2 * M_PI;
      p.length_mm = radius * std::fabs(sweep);
      tangent(sx, sy, ccw, p.start_dir);
      tangent(ex, ey, ccw, p.end_dir);
      p.cruise_mm_s = std::min(p.length_mm / p.time_s, std::sqrt(o.accel_mm_s2 * radius));
    } else {
      p.length_mm = std::hypot(static_cast<double>(b.dx), static_cast<double>(b.dy)) * blu_mm;
      unit(static_cast<double>(b.dx), static_cast<double>(b.dy), p.start_dir);
      p.end_dir[0] = p.start_dir[0];
      p.end_dir[1] = p.start_dir[1];
      p.cruise_mm_s = p.length_mm / p.time_s;
    }
    p.accel_mm_s2 = ramp_accel * p.length_mm / n;
    path.push_back(p);
  }
  // Junction speeds: the corner rule, both blocks' rates, rest at a stop or a still block.
  std::vector<double> junction(path.size() > 0 ? path.size() - 1 : 0);
  for (size_t i = 0; i < junction.size(); ++i) {
    const PathBlock &a = path[i], &b = path[i + 1];
    junction[i] = a.stops_after || b.stops_before || a.length_mm <= 0 || b.length_mm <= 0
                      ? 0
                      : std::min({junction_limit(a.end_dir, b.start_dir, o.accel_mm_s2, o.junction_deviation_mm),
                                  a.cruise_mm_s, b.cruise_mm_s});
  }
  for (unsigned k : o.lookaheads) plan.continuous.push_back({k, continuous_seconds(path, junction, k)});
  return plan;
}

}  // namespace ncinterp::checker
