// SVG figures for ncinterp's reports (check, sweep, methods): a page of panels, each a 2-D
// chart with titled axes, line/point series, horizontal bands and a legend.
// Idea: the drawing is PLplot's (Debian's libplplot, its svg driver); this file only says
// what a chart holds, so callers build plain data and never touch PLplot's global state.
// render_svg returns the document as text, so the caller writes it atomically with the
// rest of its outputs (sw/host/common/atomic_file.h).
#pragma once
#include <optional>
#include <string>
#include <vector>

namespace ncinterp::plot {

enum class Scale { kLinear, kLog10 };

// Colours of the fixed palette (dark enough to read on white, distinct in grey print).
enum class Colour { kBlack, kRed, kBlue, kGreen, kOrange, kPurple, kBrown, kGrey, kCyan };

enum class Marker { kNone, kDot, kCross, kCircle, kSquare };

struct Series {
  std::string label;          // legend entry; empty: not in the legend
  std::vector<double> x, y;   // same length; on a log axis values <= 0 are left out
  Colour colour = Colour::kBlack;
  bool line = true;           // join the points
  bool dashed = false;
  double width = 1.0;         // line width
  Marker marker = Marker::kNone;
};

// A horizontal band y_low..y_high across the panel (e.g. the tolerance band +-delta).
struct Band {
  std::string label;
  double y_low = 0.0, y_high = 0.0;
  Colour colour = Colour::kGreen;
};

// A rectangle outlined on the panel (e.g. where the zoomed panel looks).
struct Box {
  double x_low = 0.0, x_high = 0.0, y_low = 0.0, y_high = 0.0;
  Colour colour = Colour::kGrey;
};

struct Range {
  double low = 0.0, high = 1.0;
};

struct Panel {
  std::string title, x_label, y_label;
  Scale x_scale = Scale::kLinear, y_scale = Scale::kLinear;
  bool equal_aspect = false;     // one unit on x is as long as one on y (drawings in mm)
  std::optional<Range> x_range;  // default: the data's extent with a small margin
  std::optional<Range> y_range;
  std::vector<Band> bands;       // drawn first, under the series
  std::vector<Series> series;
  std::vector<Box> boxes;
  bool legend = true;            // when any series or band has a label
  int columns_spanned = 1;       // grid cells the panel takes in its row
};

struct Figure {
  std::string title;           // over the whole page; may be empty
  int columns = 1, rows = 1;   // panels fill the grid row by row
  int width_px = 1000, height_px = 700;
  std::vector<Panel> panels;   // fill the grid row by row, each over its columns_spanned
};

// The figure as an SVG document. Throws std::invalid_argument for a malformed figure
// (series with x and y of different lengths, panels that do not fit the grid, a
// non-positive log range).
std::string render_svg(const Figure& figure);

}  // namespace ncinterp::plot
