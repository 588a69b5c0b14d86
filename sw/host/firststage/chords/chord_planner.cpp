// Chord planner (see chord_planner.h).
#include "chords/chord_planner.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include "chords/chord_deviation.h"
#include "chords/chord_methods.h"

namespace ncinterp::firststage {
namespace {

// First attempt aims this far (BLU) inside delta: rounding the end moves the line by at
// most half a BLU at its middle. Each retry aims another half BLU lower.
constexpr double kFirstMargin = 0.25;
constexpr double kRetryStep = 0.5;
constexpr int kRetries = 4;

// Floating-point noise allowed on top of delta, relative to the coordinates' size: the
// deviation of a chord whose end is exactly delta off the curve (a method-3 end rounded
// outward) evaluates to delta + a few ulps; without this the next chord, which starts
// there, would be rejected for every end and the planner would find none. 1e-12 of the
// coordinates is 2e-9 BLU for a 2 mm circle at 1 um, far below anything physical.
constexpr double kRoundoff = 1e-12;

int64_t inf_norm(GridPoint a, GridPoint b) {
  return std::max(std::llabs(a.x - b.x), std::llabs(a.y - b.y));
}

}  // namespace

GridPoint round_to_grid(Vec2 v) { return {std::llround(v.x), std::llround(v.y)}; }

bool ChordPlanner::admissible(const Span& span, GridPoint p, double ta, GridPoint q,
                              double tb) const {
  if (q == p || !(tb > ta) || inf_norm(p, q) > opt_.max_inc) return false;
  const double noise = kRoundoff * (1.0 + static_cast<double>(std::max(inf_norm(p, {}), inf_norm(q, {}))));
  return chord_deviation(span, to_vec(p), to_vec(q), ta, tb) <= opt_.delta + noise;
}

bool ChordPlanner::round_end(const Span& span, GridPoint p, double ta, Vec2 e, double te,
                             GridPoint end, GridPoint* q, double* tb) const {
  const int64_t fx = static_cast<int64_t>(std::floor(e.x)), fy = static_cast<int64_t>(std::floor(e.y));
  bool found = false;
  double best = ta;
  auto consider = [&](GridPoint c) {
    const double t = c == end ? span.t_end() : foot_parameter(span, to_vec(c), te, ta, span.t_end());
    // Only the span's own end vertex may sit at its end parameter.
    if (c != end && t >= span.t_end()) return;
    if (t > best && admissible(span, p, ta, c, t) && leaves_room(span, c, t, end)) {
      best = t;
      *q = c;
      *tb = t;
      found = true;
    }
  };
  for (int dy = 0; dy <= 1; ++dy)
    for (int dx = 0; dx <= 1; ++dx) consider({fx + dx, fy + dy});
  if (found) return true;
  for (int dy = -1; dy <= 2; ++dy)  // the ring around those four
    for (int dx = -1; dx <= 2; ++dx)
      if (dx < 0 || dx > 1 || dy < 0 || dy > 1) consider({fx + dx, fy + dy});
  return found;
}

bool ChordPlanner::leaves_room(const Span& span, GridPoint c, double tc, GridPoint end) const {
  const double near = 2.0 * opt_.delta + 2.0;
  if (c == end || static_cast<double>(inf_norm(c, end)) >= near) return true;
  // Near the end in the plane is not near it along the curve when the curve comes back
  // (a closed circle, an airfoil's trailing edge, a delta as large as the part): then
  // more chords follow anyway. Nor can a register narrower than the gap take it in one.
  if (inf_norm(c, end) > opt_.max_inc) return true;
  // (Twice the distance: more than any straight-ish end, whose length is at most sqrt(2)
  // times the max-norm gap, so the usual case is decided as before.)
  double along = 0.0;
  constexpr int kSteps = 16;
  Vec2 prev = to_vec(c);
  for (int k = 1; k <= kSteps && along < 2.0 * near; ++k) {
    const Vec2 next = span.point(tc + (span.t_end() - tc) * k / kSteps);
    along += norm(next - prev);
    prev = next;
  }
  if (along >= 2.0 * near) return true;
  return admissible(span, c, tc, end, span.t_end());
}

bool ChordPlanner::ends_at_crossing(const Span& span, const ChordSolution& sol, double ta,
                                    GridPoint end) const {
  // Only a two-sided chord whose far end leaves less than one chord's worth of the span.
  if (sol.t_cross >= sol.t_end || span.t_end() - sol.t_end >= sol.t_end - ta) return false;
  const Vec2 c = span.point(sol.t_cross);
  const GridPoint g = round_to_grid(c);
  const double tc = foot_parameter(span, to_vec(g), sol.t_cross, ta, span.t_end());
  return admissible(span, g, tc, end, span.t_end());
}

bool ChordPlanner::fallback(const Span& span, GridPoint p, double ta, GridPoint end,
                            GridPoint* q, double* tb) const {
  double lo = ta, hi = span.t_end();
  bool found = false;
  // Until the two ends are within half a BLU: finer steps round to the same grid points.
  // (At least one step: a closed span starts and ends at the same point.)
  for (int it = 0; it < 60 && (it == 0 || norm(span.point(hi) - span.point(lo)) > 0.5); ++it) {
    const double mid = 0.5 * (lo + hi);
    Vec2 e = span.point(mid);
    // Respect the register width along the way.
    const Vec2 d = e - to_vec(p);
    const double m = std::max(std::fabs(d.x), std::fabs(d.y));
    if (m > opt_.max_inc - 1) {
      hi = mid;
      continue;
    }
    GridPoint c;
    double t;
    if (round_end(span, p, ta, e, mid, end, &c, &t)) {
      lo = mid;
      *q = c;
      *tb = t;
      found = true;
    } else {
      hi = mid;
    }
  }
  return found;
}

void ChordPlanner::plan(const Span& span, GridPoint start, GridPoint end,
                        std::vector<ChordEnd>& out) {
  const double t_hi = span.t_end();
  GridPoint p = start;
  double ta = 0.0, trial_step = 0.0;
  for (;;) {
    if (admissible(span, p, ta, end, t_hi)) {
      out.push_back({end, span.size() - 1});
      ++stats_.chords;
      return;
    }
    GridPoint q;
    double tb = 0.0;
    bool placed = false;
    double target = opt_.delta - kFirstMargin;
    for (int attempt = 0; attempt <= kRetries && !placed && target > 0; ++attempt) {
      if (attempt > 0) ++stats_.retries;
      const ChordRequest req{to_vec(p), ta, t_hi, target};
      ChordSolution sol = opt_.method == 1   ? trial_chord(span, req, &trial_step)
                          : opt_.method == 2 ? one_sided_chord(span, req)
                                             : two_sided_chord(span, req);
      if (!sol.ok) break;
      Vec2 e = sol.end;
      double te = sol.t_end;
      // Tamm's fig. 9: end at the crossing.
      if ((sol.reaches_end && sol.t_cross < t_hi) || ends_at_crossing(span, sol, ta, end)) {
        te = sol.t_cross;
        e = span.point(te);
      }
      // The paper's dy_max: keep the part of the chord that fits the register.
      const Vec2 d = e - to_vec(p);
      const double m = std::max(std::fabs(d.x), std::fabs(d.y));
      const double cap = static_cast<double>(opt_.max_inc - 1);
      if (m > cap) {
        const double k = cap / m;
        e = to_vec(p) + k * d;
        te = foot_parameter(span, e, ta + k * (te - ta), ta, t_hi);
      }
      placed = round_end(span, p, ta, e, te, end, &q, &tb);
      target -= attempt == 0 ? kRetryStep - kFirstMargin : kRetryStep;
    }
    if (!placed) {
      ++stats_.fallbacks;
      if (!fallback(span, p, ta, end, &q, &tb))
        throw std::runtime_error("no chord within the tolerance fits at grid point (" +
                                 std::to_string(p.x) + ", " + std::to_string(p.y) + ")");
    }
    out.push_back({q, span.index(tb)});
    ++stats_.chords;
    if (q == end) return;
    p = q;
    ta = tb;
  }
}

}  // namespace ncinterp::firststage
