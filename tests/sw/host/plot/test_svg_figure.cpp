// Tests of the SVG figure library: the document is well-formed SVG, holds what the figure
// says (titles, labels, legend entries, one polyline per drawable run), honours log axes
// and equal aspect, and malformed figures are refused before anything is drawn.
#include <gtest/gtest.h>

#include <regex>
#include <stdexcept>

#include "plot/svg_figure.h"

namespace ncinterp::plot {
namespace {

// PLplot's svg driver writes every character of a text as an entity (&#x6d;); the plain
// text of the document, for finding labels in it.
std::string decoded_text(const std::string& svg) {
  std::string out;
  const std::regex entity("&#x([0-9a-fA-F]+);");
  for (auto it = std::sregex_iterator(svg.begin(), svg.end(), entity); it != std::sregex_iterator(); ++it) {
    const unsigned long cp = std::stoul((*it)[1], nullptr, 16);
    if (cp < 0x80) out += static_cast<char>(cp);
    else out += '?';
    if (it->suffix().str().compare(0, 3, "&#x") != 0) out += '\n';
  }
  return out;
}

Figure one_panel(Panel p) {
  Figure f;
  f.panels.push_back(std::move(p));
  return f;
}

TEST(SvgFigure, DocumentCarriesTitlesLabelsAndLegend) {
  Panel p;
  p.title = "radial error";
  p.x_label = "h";
  p.y_label = "error (mm)";
  p.series.push_back({"K4", {1, 2, 3}, {1, 4, 9}, Colour::kRed});
  p.bands.push_back({"tolerance", -1.0, 1.0, Colour::kGreen});
  Figure f = one_panel(p);
  f.title = "methods";
  const std::string svg = render_svg(f);
  EXPECT_EQ(svg.rfind("<?xml", 0), 0u);
  EXPECT_NE(svg.find("</svg>"), std::string::npos);
  // PLplot writes each text as its own <text> element; the strings appear verbatim.
  const std::string text = decoded_text(svg);
  for (const char* s : {"radial error", "error (mm)", "K4", "tolerance", "methods"})
    EXPECT_NE(text.find(s), std::string::npos) << s;
  EXPECT_NE(svg.find("#C81E1E"), std::string::npos) << "the red series is drawn in red";
}

TEST(SvgFigure, LogAxisDropsNonPositivePointsAndSplitsTheLine) {
  Panel p;
  p.x_scale = p.y_scale = Scale::kLog10;
  p.legend = false;
  // Two runs of drawable points separated by a zero: two polylines in the series' colour.
  p.series.push_back({"", {1e-4, 1e-3, 1e-2, 1e-1, 1.0}, {1e-8, 1e-6, 0.0, 1e-2, 1.0},
                      Colour::kPurple});
  const std::string svg = render_svg(one_panel(p));
  const std::regex purple_line("stroke=\"#8232A0\"[^/]*points=\"[^\"]*\"");
  EXPECT_EQ(std::distance(std::sregex_iterator(svg.begin(), svg.end(), purple_line),
                          std::sregex_iterator()),
            2);
}

TEST(SvgFigure, LogAxisWithinOneDecadeStillHasDecadeLabels) {
  Panel p;
  p.y_scale = Scale::kLog10;
  p.legend = false;
  p.series.push_back({"", {1, 2, 3}, {2.0, 3.0, 5.0}, Colour::kBlue});  // no decade inside
  const std::string text = decoded_text(render_svg(one_panel(p)));
  // PLplot writes 10^n as "10" and the exponent as separate texts.
  EXPECT_NE(text.find("10\n0"), std::string::npos) << text;
  EXPECT_NE(text.find("10\n1"), std::string::npos) << text;
}

TEST(SvgFigure, EqualAspectGivesSquareUnits) {
  // A 1 x 1 square in a wide page: its outline must come out as wide as it is tall.
  Panel p;
  p.equal_aspect = true;
  p.legend = false;
  p.x_range = Range{0, 1};
  p.y_range = Range{0, 1};
  p.series.push_back({"", {0, 1, 1, 0, 0}, {0, 0, 1, 1, 0}, Colour::kBlue});
  Figure f = one_panel(p);
  f.width_px = 1200, f.height_px = 500;
  const std::string svg = render_svg(f);
  std::smatch m;
  const std::regex blue("stroke=\"#1E50C8\"[^/]*points=\"([^\"]*)\"");
  ASSERT_TRUE(std::regex_search(svg, m, blue));
  double xmin = 1e9, xmax = -1e9, ymin = 1e9, ymax = -1e9;
  const std::string pts = m[1];
  const std::regex pair("([-0-9.]+),([-0-9.]+)");
  for (auto it = std::sregex_iterator(pts.begin(), pts.end(), pair); it != std::sregex_iterator(); ++it) {
    const double x = std::stod((*it)[1]), y = std::stod((*it)[2]);
    xmin = std::min(xmin, x), xmax = std::max(xmax, x), ymin = std::min(ymin, y), ymax = std::max(ymax, y);
  }
  EXPECT_GT(xmax - xmin, 100.0);
  EXPECT_NEAR(xmax - xmin, ymax - ymin, 2.0);
}

TEST(SvgFigure, MalformedFiguresAreRefused) {
  Panel p;
  p.series.push_back({"bad", {1, 2}, {1}, Colour::kBlack});
  EXPECT_THROW(render_svg(one_panel(p)), std::invalid_argument);
  Figure two;
  two.panels.resize(2);
  EXPECT_THROW(render_svg(two), std::invalid_argument);
  Figure wide;
  wide.columns = 2;
  wide.panels.resize(1);
  wide.panels[0].columns_spanned = 3;
  EXPECT_THROW(render_svg(wide), std::invalid_argument);
  Figure overflow;  // 1 + 2 columns: the wide panel starts row 2, which does not exist
  overflow.columns = 2;
  overflow.panels.resize(2);
  overflow.panels[1].columns_spanned = 2;
  EXPECT_THROW(render_svg(overflow), std::invalid_argument);
  overflow.rows = 2;
  EXPECT_NO_THROW(render_svg(overflow));
  Panel log;
  log.x_scale = Scale::kLog10;
  log.x_range = Range{0.0, 1.0};
  EXPECT_THROW(render_svg(one_panel(log)), std::invalid_argument);
}

TEST(SvgFigure, ManyPanelsAndRepeatedRendersAreIndependent) {
  Figure f;
  f.columns = 2, f.rows = 2;
  for (int i = 0; i < 4; ++i) {
    Panel p;
    p.title = "panel " + std::to_string(i);
    p.series.push_back({"s", {0, 1}, {0, double(i)}, Colour::kGreen});
    f.panels.push_back(p);
  }
  const std::string a = render_svg(f), b = render_svg(f);
  EXPECT_EQ(a, b);
  const std::string text = decoded_text(a);
  for (int i = 0; i < 4; ++i) EXPECT_NE(text.find("panel " + std::to_string(i)), std::string::npos);
}

}  // namespace
}  // namespace ncinterp::plot
