// Series for the check's SVG (see check_plot_data.h).
#include "check_plot_data.h"

#include <algorithm>
#include <cmath>

namespace ncinterp::checker {
namespace {

using firststage::Segment;

// Samples of a segment (BLU) as mm, n + 1 points over [u0, u1].
void sample(const Segment& s, double u0, double u1, int n, double blu, Polyline& out) {
  for (int i = 0; i <= n; ++i) {
    const Vec2 p = s.point(u0 + (u1 - u0) * i / n);
    out.push_back({p.x * blu, p.y * blu});
  }
}

// A point of a segment moved `offset` BLU along its normal to the left (negative: right):
// the cutter-centre path at that point when the cutter runs on that side.
Vec2 offset_point(const Segment& s, double u, double offset) {
  const firststage::CurvePoint c = s.eval(u);
  const double len = std::hypot(c.d1.x, c.d1.y);
  if (offset == 0.0 || len == 0.0) return c.p;
  return Vec2{c.p.x - c.d1.y / len * offset, c.p.y + c.d1.x / len * offset};
}

int samples_for(const Segment& s) {
  if (s.is_arc()) return std::max(8, static_cast<int>(std::fabs(s.sweep()) / (M_PI / 180)));
  return s.kind() == firststage::SegmentKind::kLine ? 1 : 64;
}

// Liang-Barsky: the part of a-b inside w; false if none.
bool clip(PlotPoint& a, PlotPoint& b, const PlotWindow& w) {
  double t0 = 0, t1 = 1;
  const double dx = b.x - a.x, dy = b.y - a.y;
  const double p[4] = {-dx, dx, -dy, dy};
  const double q[4] = {a.x - w.x0, w.x1 - a.x, a.y - w.y0, w.y1 - a.y};
  for (int i = 0; i < 4; ++i) {
    if (p[i] == 0) {
      if (q[i] < 0) return false;
      continue;
    }
    const double t = q[i] / p[i];
    if (p[i] < 0) t0 = std::max(t0, t);
    else t1 = std::min(t1, t);
  }
  if (t0 > t1) return false;
  const PlotPoint a0 = a;
  a = {a0.x + t0 * dx, a0.y + t0 * dy};
  b = {a0.x + t1 * dx, a0.y + t1 * dy};
  return true;
}

void grow(PlotWindow& w, PlotPoint p) {
  w.x0 = std::min(w.x0, p.x), w.y0 = std::min(w.y0, p.y);
  w.x1 = std::max(w.x1, p.x), w.y1 = std::max(w.y1, p.y);
}

}  // namespace

CheckPlotData check_plot_data(const CheckOutcome& o, double tol_mm, double clock_hz, size_t bins,
                              size_t speed_bins) {
  CheckPlotData d;
  d.tol_mm = tol_mm;
  const TrajectoryChecker& c = *o.checker;
  const double blu = o.blu_mm;
  const GridPoint start = o.reference ? o.reference->start() : GridPoint{};
  auto mm = [&](GridPoint p) { return PlotPoint{(start.x + p.x) * blu, (start.y + p.y) * blu}; };
  auto mmv = [&](Vec2 p) { return PlotPoint{(start.x + p.x) * blu, (start.y + p.y) * blu}; };

  d.overview = {INFINITY, INFINITY, -INFINITY, -INFINITY};
  if (o.reference) {
    for (const Segment& s : o.reference->cutting_segments()) {
      d.contour.emplace_back();
      sample(s, 0, 1, samples_for(s), blu, d.contour.back());
      for (const PlotPoint& p : d.contour.back()) grow(d.overview, p);
    }
    for (const Segment& s : o.reference->rapid_segments()) {
      d.rapids.emplace_back();
      sample(s, 0, 1, 1, blu, d.rapids.back());
    }
  }
  d.programmed.push_back(mm({0, 0}));
  for (const ProgrammedBlock& b : c.blocks()) {
    if (b.is_arc()) {
      const int n = std::max(4, static_cast<int>(std::fabs(b.sweep()) / (M_PI / 180)));
      for (int i = 1; i <= n; ++i) d.programmed.push_back(mmv(b.point_at(static_cast<double>(i) / n)));
    } else {
      d.programmed.push_back(mm(b.end));
    }
    d.vertices.push_back(mm(b.end));
  }
  for (const PlotPoint& p : d.programmed) grow(d.overview, p);
  const double span = std::max({d.overview.x1 - d.overview.x0, d.overview.y1 - d.overview.y0, 1e-3});
  d.overview = {d.overview.x0 - 0.04 * span, d.overview.y0 - 0.04 * span, d.overview.x1 + 0.04 * span,
                d.overview.y1 + 0.04 * span};

  // The worst point and its foot.
  d.total_measured = c.total_error().count > 0;
  d.cutter = o.reference && o.reference->radius_blu() > 0;
  const ErrorStat& worst = d.total_measured ? c.total_error() : c.path_error();
  if (worst.count > 0) {
    d.has_worst = true;
    d.worst = mm(worst.position);
    d.worst_error_mm = worst.max * blu;
    d.worst_block = c.blocks()[worst.block].tape.n;
    d.worst_cycle = worst.cycle;
    if (d.total_measured) {
      // The foot on the part; with a cutter, the point R from it towards the tool, on the
      // cutter-centre path the total error is measured against.
      Vec2 foot = o.reference->measure(to_vec(worst.position)).foot;
      const Vec2 to_tool = to_vec(worst.position) - foot;
      const double d_part = std::hypot(to_tool.x, to_tool.y);
      if (o.reference->radius_blu() > 0 && d_part > 0)
        foot = foot + (o.reference->radius_blu() / d_part) * to_tool;
      d.worst_foot = mmv(foot);
    } else {
      double along = 0;
      const ProgrammedBlock& b = c.blocks()[worst.block];
      distance_to_block(b, to_vec(worst.position), &along);
      d.worst_foot = mmv(b.point_at(along));
    }
    const double h = std::max({3.0 * tol_mm, 3.0 * d.worst_error_mm, 20.0 * blu});
    d.zoom = {d.worst.x - h, d.worst.y - h, d.worst.x + h, d.worst.y + h};
  }

  if (d.has_worst && o.reference) {
    // The path the total error is measured against inside the zoom: the contour, or with a
    // cutter the contour moved R along its normal to the cutter's side. Coarse samples find
    // the pieces, then dense samples there.
    const double offset = o.reference->radius_blu() * (o.reference->cutter_left() ? 1.0 : -1.0);
    const PlotWindow& z = d.zoom;
    const PlotWindow wide{z.x0 - (z.x1 - z.x0), z.y0 - (z.y1 - z.y0), z.x1 + (z.x1 - z.x0), z.y1 + (z.y1 - z.y0)};
    for (const Segment& s : o.reference->cutting_segments()) {
      const int n0 = 4096, dense = 64;
      auto at = [&](double u) {
        const Vec2 p = offset_point(s, u, offset);
        return PlotPoint{p.x * blu, p.y * blu};
      };
      Polyline run;
      for (int i = 0; i < n0; ++i) {
        const double u0 = static_cast<double>(i) / n0, u1 = static_cast<double>(i + 1) / n0;
        PlotPoint pa = at(u0), pb = at(u1);
        if (!clip(pa, pb, wide)) {
          if (!run.empty()) d.zoom_contour.push_back(std::move(run)), run.clear();
          continue;
        }
        for (int k = run.empty() ? 0 : 1; k <= dense; ++k) run.push_back(at(u0 + (u1 - u0) * k / dense));
      }
      if (!run.empty()) d.zoom_contour.push_back(std::move(run));
    }
  }
  if (d.has_worst) {
    for (size_t k = 0; k + 1 < d.programmed.size(); ++k) {
      PlotPoint a = d.programmed[k], b = d.programmed[k + 1];
      if (!clip(a, b, d.zoom)) continue;
      // A new run unless this piece continues the last one.
      if (d.zoom_programmed.empty() ||
          std::hypot(d.zoom_programmed.back().back().x - a.x, d.zoom_programmed.back().back().y - a.y) > 1e-12)
        d.zoom_programmed.push_back({a});
      d.zoom_programmed.back().push_back(b);
    }
  }

  // Pulses: zoom runs and the error along the path.
  const std::vector<PulseSample>& pulses = c.pulses();
  std::vector<double> s_of(pulses.size());
  PlotPoint prev = mm({0, 0});
  double s = 0.0;
  Polyline run;
  for (size_t i = 0; i < pulses.size(); ++i) {
    const PlotPoint p = mm(pulses[i].position);
    s += std::hypot(p.x - prev.x, p.y - prev.y);
    s_of[i] = s;
    if (d.has_worst) {
      if (d.zoom.contains(p)) {
        if (run.empty() && i > 0) run.push_back(prev);  // enter the window from outside
        run.push_back(p);
      } else if (!run.empty()) {
        run.push_back(p);
        d.zoom_pulses.push_back(std::move(run));
        run.clear();
      }
    }
    prev = p;
  }
  if (!run.empty()) d.zoom_pulses.push_back(std::move(run));
  d.path_length_mm = s;
  if (!pulses.empty() && bins > 0) {
    d.error_bins.resize(bins);
    for (size_t b = 0; b < bins; ++b) d.error_bins[b].s_mm = s * b / bins;
    for (size_t i = 0; i < pulses.size(); ++i) {
      const size_t b = std::min(bins - 1, static_cast<size_t>(s > 0 ? s_of[i] / s * bins : 0));
      ErrorBin& e = d.error_bins[b];
      e.path_max = std::max(e.path_max, pulses[i].path_error * blu);
      if (pulses[i].total_error >= 0) {
        const double t = pulses[i].total_error * blu;
        e.total_max = std::max(e.total_max, t);
        e.total_min = e.total_min < 0 ? t : std::min(e.total_min, t);
      }
    }
  }
  if (!pulses.empty() && speed_bins > 0 && clock_hz > 0) {
    // Clocks 0 .. the last pulse's, in bins of equal time; each pulse's steps (its move
    // from the last position, one BLU per axis) are counted in the bin of its clock.
    const uint64_t span = pulses.back().cycle + 1;
    const double bin_s = static_cast<double>(span) / speed_bins / clock_hz;
    d.speed_bins.resize(speed_bins);
    for (size_t b = 0; b < speed_bins; ++b) d.speed_bins[b].t_s = bin_s * b;
    GridPoint last{0, 0};
    for (const PulseSample& p : pulses) {
      SpeedBin& b = d.speed_bins[std::min(speed_bins - 1, static_cast<size_t>(p.cycle * speed_bins / span))];
      b.x_mm_min += std::llabs(p.position.x - last.x);
      b.y_mm_min += std::llabs(p.position.y - last.y);
      last = p.position;
    }
    const double mm_min_per_step = blu * 60.0 / bin_s;
    for (SpeedBin& b : d.speed_bins) b.x_mm_min *= mm_min_per_step, b.y_mm_min *= mm_min_per_step;
  }
  return d;
}

}  // namespace ncinterp::checker
