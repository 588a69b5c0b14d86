// SVG of the methods study (see methods_plot.h), drawn with sw/host/plot.
// Idea: errors are divided by R, so on log axes a method's curve is a straight line whose
// slope is its order in h and whose height at h = 1 is its constant; the paper's formula
// in the same colour shows at a glance where the paper is right. Points that round-off
// decides (method_study.h) are left out, as they are of the fits.
#include "methods_plot.h"

#include <string>

#include "paper_claims.h"
#include "plot/svg_figure.h"

namespace ncinterp::sampled {
namespace {

using plot::Colour;
using plot::Series;

Colour colour_of(Method m) {
  switch (m) {
    case Method::kL1: return Colour::kGrey;
    case Method::kK1: return Colour::kRed;
    case Method::kK2: return Colour::kBlue;
    case Method::kK3: return Colour::kGreen;
    case Method::kK4: return Colour::kOrange;
    case Method::kK5: return Colour::kPurple;
    case Method::kK6: return Colour::kBrown;
    case Method::kK7: return Colour::kCyan;
  }
  return Colour::kBlack;
}

Series series_of(Method m, std::string label) {
  Series s;
  s.label = std::move(label);
  s.colour = colour_of(m);
  s.marker = plot::Marker::kDot;
  return s;
}

plot::Panel log_panel(std::string title, std::string y_label, int columns) {
  plot::Panel p;
  p.title = std::move(title);
  p.x_label = "h";
  p.y_label = std::move(y_label);
  p.x_scale = p.y_scale = plot::Scale::kLog10;
  p.columns_spanned = columns;
  return p;
}

}  // namespace

std::string methods_svg(const Study& study) {
  const double r0 = study.config.radii_mm.front();
  plot::Panel quarter = log_panel(
      "Quarter circle: largest radial error, double (dashed: the paper's formula)",
      "error / R", 2);
  // One legend for the figure: the lower panels use the same colours.
  plot::Panel drift = log_panel("Growth of the error per turn, double", "drift per turn / R", 1);
  plot::Panel fixed = log_panel("Quarter circle, " + std::to_string(study.config.word_bits) + "-bit fixed point",
                                "error / R", 1);
  drift.legend = fixed.legend = false;
  for (Method m : kAllMethods) {
    const std::string name = method_name(m);
    Series q = series_of(m, m == Method::kL1 ? "L1 (end point / L)" : name + " (" + method_description(m) + ")");
    q.line = m != Method::kL1;  // L1's end error jumps with the remainder of 1/h: points only
    Series d = series_of(m, name), f = series_of(m, name);
    Series paper = series_of(m, "");
    paper.marker = plot::Marker::kNone;
    paper.dashed = true;
    const PaperClaim* claim = quarter_claim(m);
    for (const StudyRow& r : study.rows) {
      if (r.method != m || r.radius != r0) continue;
      // L1 lies on its line to round-off; what it gets wrong is where it ends.
      if (m == Method::kL1 || !r.roundoff_limited) {
        q.x.push_back(r.h);
        q.y.push_back((m == Method::kL1 ? r.end_error : r.error) / r.radius);
      }
      if (r.drifts) {
        d.x.push_back(r.h);
        d.y.push_back(r.drift_per_turn / r.radius);
      }
      if (m != Method::kL1) {
        f.x.push_back(r.h);
        f.y.push_back(r.fixed_error / r.radius);
      }
      if (claim) {
        paper.x.push_back(r.h);
        paper.y.push_back(r.paper_error / r.radius);
      }
    }
    quarter.series.push_back(q);
    if (claim) quarter.series.push_back(paper);
    if (!d.x.empty()) drift.series.push_back(d);
    if (!f.x.empty()) fixed.series.push_back(f);
  }
  plot::Figure fig;
  fig.title = "Reference-word interpolators of paper 003: error against h";
  fig.columns = 2;
  fig.rows = 2;
  fig.width_px = 1400;
  fig.height_px = 1200;
  fig.panels = {quarter, drift, fixed};
  return plot::render_svg(fig);
}

}  // namespace ncinterp::sampled
