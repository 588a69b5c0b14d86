// SVG plot of a check (see check_plot.h).
// Idea: four panels from check_plot_data's series: the whole part (equal axes, mm), the
// worst point up close (the staircase of single pulses against the chord and the contour),
// the error along the path against the tolerance band, and the feed profile (each axis's
// speed against time). Nothing is computed here but
// the mapping of those series to what the reader sees.
#include "check_plot.h"

#include <cmath>
#include <cstdio>
#include <limits>

#include "check_plot_data.h"
#include "plot/svg_figure.h"

namespace ncinterp::checker {
namespace {

using plot::Colour;
using plot::Marker;
using plot::Panel;
using plot::Series;

Series series_of(const Polyline& line, std::string label, Colour colour, double width = 1.0) {
  Series s{std::move(label), {}, {}, colour};
  s.width = width;
  for (const PlotPoint& p : line) s.x.push_back(p.x), s.y.push_back(p.y);
  return s;
}

// Several runs as one series: NaN between runs breaks the line; only the first is labelled.
Series series_of(const std::vector<Polyline>& runs, std::string label, Colour colour, double width = 1.0) {
  Series s = series_of(Polyline{}, std::move(label), colour, width);
  for (const Polyline& run : runs) {
    for (const PlotPoint& p : run) s.x.push_back(p.x), s.y.push_back(p.y);
    s.x.push_back(std::numeric_limits<double>::quiet_NaN());
    s.y.push_back(std::numeric_limits<double>::quiet_NaN());
  }
  return s;
}

Series point(PlotPoint p, std::string label, Colour colour, Marker marker) {
  Series s{std::move(label), {p.x}, {p.y}, colour};
  s.line = false;
  s.marker = marker;
  return s;
}

// Errors are shown in µm: an engineer reads "7.3 µm" at once, and PLplot would otherwise
// put a x10^-3 factor on the axis.
std::string um_text(double mm) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.1f", mm * 1000.0);
  return buf;
}

// A panel of the part's plane: mm on both axes at equal scale, showing window w.
Panel plane_panel(std::string title, const PlotWindow& w) {
  Panel p;
  p.title = std::move(title);
  p.x_label = "x (mm)";
  p.y_label = "y (mm)";
  p.equal_aspect = true;
  p.x_range = plot::Range{w.x0, w.x1};
  p.y_range = plot::Range{w.y0, w.y1};
  return p;
}

Panel overview_panel(const CheckPlotData& d) {
  Panel p = plane_panel("part: contour, programmed blocks, worst point", d.overview);
  if (!d.contour.empty()) p.series.push_back(series_of(d.contour, "contour", Colour::kBlack, 1.5));
  if (!d.rapids.empty()) {
    p.series.push_back(series_of(d.rapids, "rapid (G0)", Colour::kGrey));
    p.series.back().dashed = true;
  }
  p.series.push_back(series_of(d.programmed, "programmed blocks", Colour::kBlue));
  if (d.has_worst) {
    p.series.push_back(point(d.worst, "worst point", Colour::kRed, Marker::kCircle));
    p.boxes.push_back({d.zoom.x0, d.zoom.x1, d.zoom.y0, d.zoom.y1, Colour::kRed});
  }
  return p;
}

Panel zoom_panel(const CheckPlotData& d) {
  Panel p = plane_panel("worst point: N" + std::to_string(d.worst_block) + ", clock " +
                            std::to_string(d.worst_cycle) + ", " + um_text(d.worst_error_mm) + " µm",
                        d.zoom);
  if (!d.zoom_contour.empty())
    p.series.push_back(series_of(d.zoom_contour, d.cutter ? "cutter-centre path (contour + R)" : "contour",
                                 Colour::kBlack, 1.5));
  if (!d.zoom_programmed.empty())
    p.series.push_back(series_of(d.zoom_programmed, "programmed block", Colour::kBlue));
  Series pulses = series_of(d.zoom_pulses, "pulse path (one BLU per step)", Colour::kRed);
  pulses.marker = Marker::kDot;
  p.series.push_back(std::move(pulses));
  Series normal = series_of(Polyline{d.worst, d.worst_foot},
                            d.total_measured ? "distance to the contour" : "distance to the block",
                            Colour::kGreen, 2.0);
  p.series.push_back(std::move(normal));
  return p;
}

Panel error_panel(const CheckPlotData& d) {
  Panel p;
  p.title = "error along the path (max and min per bin)";
  p.x_label = "path length (mm)";
  p.y_label = "error (µm)";
  p.columns_spanned = 2;
  p.bands.push_back({"tolerance (0 to " + um_text(d.tol_mm) + " µm)", 0.0, 1000.0 * d.tol_mm, Colour::kGreen});
  const double nan = std::numeric_limits<double>::quiet_NaN();
  Series total_max{"total error (to the contour), max", {}, {}, Colour::kRed};
  Series total_min{"total error, min", {}, {}, Colour::kOrange};
  Series path{"interpolator error (to the block)", {}, {}, Colour::kBlue};
  for (const ErrorBin& b : d.error_bins) {
    total_max.x.push_back(b.s_mm), total_max.y.push_back(b.total_max >= 0 ? 1000.0 * b.total_max : nan);
    total_min.x.push_back(b.s_mm), total_min.y.push_back(b.total_min >= 0 ? 1000.0 * b.total_min : nan);
    path.x.push_back(b.s_mm), path.y.push_back(1000.0 * b.path_max);
  }
  if (d.total_measured) {
    p.series.push_back(std::move(total_max));
    p.series.push_back(std::move(total_min));
  }
  p.series.push_back(std::move(path));
  return p;
}

Panel speed_panel(const CheckPlotData& d) {
  Panel p;
  p.title = "feed profile: each axis's speed against time (pulses per bin)";
  p.x_label = "time (s)";
  p.y_label = "speed (mm/min)";
  p.columns_spanned = 2;
  Series x{"X", {}, {}, Colour::kBlue}, y{"Y", {}, {}, Colour::kRed};
  for (const SpeedBin& b : d.speed_bins) {
    x.x.push_back(b.t_s), x.y.push_back(b.x_mm_min);
    y.x.push_back(b.t_s), y.y.push_back(b.y_mm_min);
  }
  p.series.push_back(std::move(x));
  p.series.push_back(std::move(y));
  return p;
}

}  // namespace

std::string check_svg(const CheckOutcome& outcome, const ReportContext& context) {
  const CheckPlotData d = check_plot_data(outcome, context.setup.tol_mm, context.setup.clock_hz);
  plot::Figure f;
  auto file_name = [](const std::string& path) { return path.substr(path.find_last_of('/') + 1); };
  f.title = "ncinterp check: " + file_name(context.tape_file) +
            (context.contour_file.empty() ? "" : " against " + file_name(context.contour_file));
  f.columns = 2;
  f.rows = 3;
  f.width_px = 1400;
  f.height_px = 1800;
  f.panels.push_back(overview_panel(d));
  if (d.has_worst) f.panels.push_back(zoom_panel(d));
  else f.panels.emplace_back().title = "no pulse: nothing to zoom on";
  f.panels.push_back(error_panel(d));
  f.panels.push_back(speed_panel(d));
  return plot::render_svg(f);
}

}  // namespace ncinterp::checker
