// SVG of the methods study (see methods_plot.h), drawn with sw/plot.
// Idea: errors are divided by R, so in double every radius falls on one curve and the
// slope on the log axes is the order in h; fixed point, which depends on R through the
// word's quantum, gets one dashed curve per radius.
#include "methods_plot.h"

#include <string>

#include "paper_claims.h"
#include "plot/svg_figure.h"

namespace ncinterp::sampled {
namespace {

using plot::Colour;
using plot::Marker;
using plot::Series;

Series series(std::string label, Colour colour, bool line, Marker marker) {
  Series s;
  s.label = std::move(label);
  s.colour = colour;
  s.line = line;
  s.marker = marker;
  return s;
}

std::string short_number(double v) {
  std::string s = std::to_string(v);
  s.erase(s.find_last_not_of('0') + 1);
  if (s.back() == '.') s.pop_back();
  return s;
}

plot::Panel panel_for(const Study& study, Method m) {
  const double r0 = study.config.radii_mm.front();
  plot::Panel p;
  p.title = std::string(method_name(m)) + " (" + method_description(m) + ")";
  p.x_label = "h";
  p.y_label = m == Method::kL1 ? "error / L" : "error / R";
  p.x_scale = p.y_scale = plot::Scale::kLog10;
  Series dbl = series(m == Method::kL1 ? "end point, double" : "quarter, double", Colour::kBlack, true, Marker::kDot);
  Series floor = series("round-off limited", Colour::kGrey, false, Marker::kCross);
  Series drift = series("drift per turn", Colour::kBlue, true, Marker::kNone);
  Series paper = series("", Colour::kRed, true, Marker::kNone);
  paper.dashed = true;
  if (const PaperClaim* c = quarter_claim(m)) paper.label = std::string("paper: ") + c->formula;
  const Colour fixed_colours[] = {Colour::kGreen, Colour::kOrange, Colour::kPurple, Colour::kBrown, Colour::kCyan};
  std::vector<Series> fixed;
  for (size_t i = 0; i < study.config.radii_mm.size(); ++i) {
    Series f = series(std::to_string(study.config.word_bits) + "-bit, R " + short_number(study.config.radii_mm[i]) +
                          " mm",
                      fixed_colours[i % 5], true, Marker::kNone);
    f.dashed = true;
    fixed.push_back(f);
  }
  for (const StudyRow& r : study.rows) {
    if (r.method != m) continue;
    for (size_t i = 0; i < study.config.radii_mm.size(); ++i)
      if (r.radius == study.config.radii_mm[i]) {
        fixed[i].x.push_back(r.h);
        fixed[i].y.push_back(r.fixed_error / r.radius);
      }
    if (r.radius != r0) continue;
    // L1 in double lies on the line to round-off; what it gets wrong is the end point.
    Series& target = m != Method::kL1 && r.roundoff_limited ? floor : dbl;
    target.x.push_back(r.h);
    target.y.push_back((m == Method::kL1 ? r.end_error : r.error) / r.radius);
    if (r.drifts) {
      drift.x.push_back(r.h);
      drift.y.push_back(r.drift_per_turn / r.radius);
    }
    if (!paper.label.empty()) {
      paper.x.push_back(r.h);
      paper.y.push_back(r.paper_error / r.radius);
    }
  }
  for (Series* s : {&dbl, &floor, &drift, &paper})
    if (!s->x.empty()) p.series.push_back(*s);
  for (Series& f : fixed) p.series.push_back(f);
  return p;
}

}  // namespace

std::string methods_svg(const Study& study) {
  plot::Figure f;
  f.title = "Reference-word interpolators (paper 003): error against h";
  // Two panels a row, tall enough for the log axes' decade labels and the legends.
  f.columns = 2;
  f.rows = 4;
  f.width_px = 1400;
  f.height_px = 2600;
  for (Method m : kAllMethods) f.panels.push_back(panel_for(study, m));
  return plot::render_svg(f);
}

}  // namespace ncinterp::sampled
