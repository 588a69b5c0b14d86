// SVG figures drawn with PLplot's svg driver (see svg_figure.h).
// Idea: the page is laid out here (a grid of panels, each with room for its labels), and
// PLplot draws each panel into its own viewport: grid, bands, series, boxes, axes, labels
// and a legend. PLplot writes to a FILE*; open_memstream turns that into a string. PLplot
// keeps global state and is not thread-safe, so one figure is drawn at a time.
#include "svg_figure.h"

#include <plplot/plstream.h>
#include <stdio.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <limits>
#include <mutex>
#include <utility>
#include <stdexcept>

namespace ncinterp::plot {
namespace {

// cmap0 index 0 is PLplot's background; the palette follows in Colour's order.
struct Rgb {
  int r, g, b;
};
constexpr Rgb kBackground{255, 255, 255};
constexpr Rgb kPalette[] = {
    {0, 0, 0},       // black
    {200, 30, 30},   // red
    {30, 80, 200},   // blue
    {20, 140, 50},   // green
    {230, 130, 0},   // orange
    {130, 50, 160},  // purple
    {140, 80, 30},   // brown
    {140, 140, 140}, // grey
    {0, 160, 170},   // cyan
};
constexpr int kPaletteSize = sizeof(kPalette) / sizeof(kPalette[0]);
constexpr int kGridColour = kPaletteSize + 1;   // light grey grid lines
constexpr int kBandBase = kPaletteSize + 2;     // translucent copies of the palette

// Layout, in px of the page: the page title's strip, the room under a panel for its tick
// labels and axis title, and one legend row.
constexpr double kTitleHeightPx = 62.0;
constexpr double kAxisBelowPx = 75.0;
constexpr double kLegendRowPx = 32.0;
constexpr double kTextScale = 0.75;  // of PLplot's default character height

int colour_index(Colour c) { return 1 + static_cast<int>(c); }
int band_index(Colour c) { return kBandBase + static_cast<int>(c); }

// Markers are drawn as text glyphs (plstring), which the svg driver writes as <text>.
const char* marker_glyph(Marker m) {
  switch (m) {
    case Marker::kDot: return "•";
    case Marker::kCross: return "×";
    case Marker::kCircle: return "○";
    case Marker::kSquare: return "□";
    case Marker::kNone: break;
  }
  return "";
}

double to_axis(double v, Scale s) { return s == Scale::kLog10 ? std::log10(v) : v; }
bool on_axis(double v, Scale s) { return std::isfinite(v) && (s == Scale::kLinear || v > 0.0); }

struct Extent {
  double low = std::numeric_limits<double>::infinity();
  double high = -std::numeric_limits<double>::infinity();
  void add(double v) {
    low = std::min(low, v);
    high = std::max(high, v);
  }
  bool empty() const { return !(low <= high); }
};

// The axis range in axis units (log10 for log axes): the given range, else the data's
// extent with a 4% margin; a zero-width extent is widened so PLplot accepts it.
Range axis_range(const std::optional<Range>& given, const Extent& data, Scale s,
                 const char* which) {
  Range r;
  if (given) {
    if (s == Scale::kLog10 && (given->low <= 0.0 || given->high <= 0.0))
      throw std::invalid_argument(std::string("plot: log ") + which + " range must be positive");
    r = {to_axis(given->low, s), to_axis(given->high, s)};
  } else if (data.empty()) {
    r = {0.0, 1.0};
  } else {
    const double margin = 0.04 * (data.high - data.low);
    r = {data.low - margin, data.high + margin};
  }
  if (!(r.high > r.low)) {
    const double pad = std::max(1e-9, std::abs(r.low) * 0.05);
    r = {r.low - pad, r.low + pad};
  }
  // A log axis is labelled at whole decades only: one that holds none is widened to the
  // decades around its data, so it always has a label at each end.
  if (s == Scale::kLog10 && std::floor(r.high) < std::ceil(r.low))
    r = {std::floor(r.low), std::ceil(r.high)};
  return r;
}

// Consecutive runs of points that can be drawn on the panel's axes, in axis units.
std::vector<std::pair<std::vector<PLFLT>, std::vector<PLFLT>>> drawable_runs(
    const Series& s, Scale xs, Scale ys) {
  std::vector<std::pair<std::vector<PLFLT>, std::vector<PLFLT>>> runs(1);
  for (size_t i = 0; i < s.x.size(); ++i) {
    if (on_axis(s.x[i], xs) && on_axis(s.y[i], ys)) {
      runs.back().first.push_back(to_axis(s.x[i], xs));
      runs.back().second.push_back(to_axis(s.y[i], ys));
    } else if (!runs.back().first.empty()) {
      runs.emplace_back();
    }
  }
  if (runs.back().first.empty()) runs.pop_back();
  return runs;
}

// The grid cell (row-major) where each panel starts: panels follow each other along a
// row; one that does not fit in the rest of its row starts the next row.
std::vector<int> first_cells(const Figure& f) {
  std::vector<int> cells;
  int cell = 0;
  for (const Panel& p : f.panels) {
    if (cell % f.columns + p.columns_spanned > f.columns) cell += f.columns - cell % f.columns;
    cells.push_back(cell);
    cell += p.columns_spanned;
  }
  return cells;
}

void check_figure(const Figure& f) {
  if (f.columns < 1 || f.rows < 1) throw std::invalid_argument("plot: the grid needs >= 1 column and row");
  for (const Panel& p : f.panels)
    if (p.columns_spanned < 1 || p.columns_spanned > f.columns)
      throw std::invalid_argument("plot: a panel spans 1 to " + std::to_string(f.columns) + " columns");
  const std::vector<int> cells = first_cells(f);
  if (!cells.empty() && cells.back() + f.panels.back().columns_spanned > f.columns * f.rows)
    throw std::invalid_argument("plot: the panels do not fit the grid");
  if (f.width_px < 100 || f.height_px < 100) throw std::invalid_argument("plot: page too small");
  for (const Panel& p : f.panels)
    for (const Series& s : p.series)
      if (s.x.size() != s.y.size())
        throw std::invalid_argument("plot: series '" + s.label + "' has x and y of different lengths");
}

// PLplot reports recoverable problems through plabort; keep the first one for an exception.
std::string g_plplot_problem;
void record_plplot_problem(const char* message) {
  if (g_plplot_problem.empty()) g_plplot_problem = message ? message : "unknown";
}

class PanelPainter {
 public:
  PanelPainter(plstream& pls, const Figure& fig) : pls_(pls), fig_(fig) {}

  // Draws panel `p` into the grid from cell `cell` (row-major) over its columns_spanned.
  void draw(const Panel& p, int cell) {
    const int col = cell % fig_.columns, row = cell / fig_.columns, span = p.columns_spanned;
    // Page fractions of the grid cell; the margins are absolute sizes (px) so labels fit
    // whatever the page size: tick labels and axis titles, the legend rows under the panel.
    const double top_reserve = fig_.title.empty() ? 0.0 : kTitleHeightPx / fig_.height_px;
    const double cw = 1.0 / fig_.columns, ch = (1.0 - top_reserve) / fig_.rows;
    const int legend_rows = (legend_entries(p) + legend_columns(p) - 1) / legend_columns(p);
    const double left = 125.0 / fig_.width_px, right = 25.0 / fig_.width_px;
    const double bottom = (kAxisBelowPx + legend_rows * kLegendRowPx) / fig_.height_px;
    const double top = 40.0 / fig_.height_px;
    double x0 = col * cw + left, x1 = (col + span) * cw - right;
    double y1 = 1.0 - top_reserve - row * ch - top, y0 = 1.0 - top_reserve - (row + 1) * ch + bottom;

    Extent ex, ey;
    for (const Series& s : p.series)
      for (size_t i = 0; i < s.x.size(); ++i)
        if (on_axis(s.x[i], p.x_scale) && on_axis(s.y[i], p.y_scale)) {
          ex.add(to_axis(s.x[i], p.x_scale));
          ey.add(to_axis(s.y[i], p.y_scale));
        }
    for (const Band& b : p.bands)
      for (double v : {b.y_low, b.y_high})
        if (on_axis(v, p.y_scale)) ey.add(to_axis(v, p.y_scale));
    Range xr = axis_range(p.x_range, ex, p.x_scale, "x");
    Range yr = axis_range(p.y_range, ey, p.y_scale, "y");

    if (p.equal_aspect) {
      // Shrink the viewport (not the data range) so one unit has the same length in x and
      // y; centre it in its cell.
      const double w_px = (x1 - x0) * fig_.width_px, h_px = (y1 - y0) * fig_.height_px;
      const double sx = w_px / (xr.high - xr.low), sy = h_px / (yr.high - yr.low);
      if (sx > sy) {
        const double w = (xr.high - xr.low) * sy / fig_.width_px, mid = 0.5 * (x0 + x1);
        x0 = mid - w / 2, x1 = mid + w / 2;
      } else {
        const double h = (yr.high - yr.low) * sx / fig_.height_px, mid = 0.5 * (y0 + y1);
        y0 = mid - h / 2, y1 = mid + h / 2;
      }
    }
    pls_.vpor(x0, x1, y0, y1);
    pls_.wind(xr.low, xr.high, yr.low, yr.high);

    // Log axes: PLplot ticks every decade, and its own labels would overlap on a long
    // range, so a label function writes 10^n only every `step` decades (about 60 px per
    // label along x, 28 px along y); log y labels are written across the axis, where a
    // short "10^-6" fits. Linear axes: PLplot's own ticks and labels, y along the axis.
    const std::string xopt = p.x_scale == Scale::kLog10 ? "lo" : "";
    const std::string yopt = p.y_scale == Scale::kLog10 ? "lov" : "";
    steps_ = {decade_step(p.x_scale, xr, (x1 - x0) * fig_.width_px / 60.0),
              decade_step(p.y_scale, yr, (y1 - y0) * fig_.height_px / 28.0)};
    pls_.slabelfunc(&PanelPainter::decade_label, &steps_);
    // Linear axes: a 1-2-5 tick step whose labels fit along the axis (y labels run along
    // it too); PLplot's automatic choice crowds short panels.
    const double xtick = linear_step(p.x_scale, xr, (x1 - x0) * fig_.width_px);
    const double ytick = linear_step(p.y_scale, yr, (y1 - y0) * fig_.height_px);
    pls_.col0(kGridColour);
    pls_.width(0.5);
    pls_.box(("g" + xopt).c_str(), xtick, 0, ("g" + yopt).c_str(), ytick, 0);

    for (const Band& b : p.bands) {
      if (!on_axis(b.y_low, p.y_scale) || !on_axis(b.y_high, p.y_scale)) continue;
      const PLFLT bx[4] = {xr.low, xr.high, xr.high, xr.low};
      const double lo = to_axis(b.y_low, p.y_scale), hi = to_axis(b.y_high, p.y_scale);
      const PLFLT by[4] = {lo, lo, hi, hi};
      pls_.col0(band_index(b.colour));
      pls_.fill(4, bx, by);
    }
    for (const Series& s : p.series) draw_series(s, p);
    for (const Box& b : p.boxes) {
      const PLFLT bx[5] = {b.x_low, b.x_high, b.x_high, b.x_low, b.x_low};
      const PLFLT by[5] = {b.y_low, b.y_low, b.y_high, b.y_high, b.y_low};
      pls_.col0(colour_index(b.colour));
      pls_.width(1.5);
      pls_.lsty(2);
      pls_.line(5, bx, by);
      pls_.lsty(1);
    }

    pls_.col0(colour_index(Colour::kBlack));
    pls_.width(1.0);
    pls_.box(("bcnst" + xopt).c_str(), xtick, 0, ("bcnst" + yopt).c_str(), ytick, 0);
    pls_.lab(p.x_label.c_str(), p.y_label.c_str(), p.title.c_str());
    if (legend_entries(p) > 0) draw_legend(p, (y1 - y0) * fig_.height_px);
  }

 private:
  // Decades between two labels of a log axis, so that at most `labels` labels fit.
  static int decade_step(Scale s, const Range& r, double labels) {
    if (s != Scale::kLog10) return 1;
    return static_cast<int>(std::max(1.0, std::ceil((r.high - r.low) / std::max(1.0, labels))));
  }

  // The smallest tick step of 1, 2 or 5 times a power of ten whose labels fit along an
  // axis of `axis_px` (a label of c characters takes about 12 c + 16 px); 0 (unused) on a
  // log axis.
  static double linear_step(Scale s, const Range& r, double axis_px) {
    if (s != Scale::kLinear) return 0.0;
    const double span = r.high - r.low;
    const double biggest = std::max(std::fabs(r.low), std::fabs(r.high));
    for (double decade = std::pow(10.0, std::floor(std::log10(span)) - 3);; decade *= 10.0)
      for (double m : {1.0, 2.0, 5.0}) {
        const double step = m * decade;
        const int decimals = std::max(0, static_cast<int>(-std::floor(std::log10(step) + 1e-9)));
        const int digits = 1 + static_cast<int>(std::max(0.0, std::floor(std::log10(biggest))));
        const int chars = digits + (r.low < 0 ? 1 : 0) + (decimals > 0 ? decimals + 1 : 0);
        if (span / step * (12.0 * chars + 16.0) <= axis_px) return step;
      }
  }

  // PLplot's custom label callback (box option "o", used on log axes only): "10^n" in
  // PLplot's superscript escapes at every step-th decade, nothing elsewhere.
  static void decade_label(PLINT axis, PLFLT value, char* label, PLINT length, PLPointer data) {
    const auto* steps = static_cast<const std::pair<int, int>*>(data);
    const int step = axis == PL_X_AXIS ? steps->first : steps->second;
    const long decade = std::lround(value);
    if (decade % step != 0) {
      label[0] = '\0';
      return;
    }
    std::snprintf(label, static_cast<size_t>(length), "10#u%ld#d", decade);
  }

  static int legend_entries(const Panel& p) {
    if (!p.legend) return 0;
    int n = 0;
    for (const Band& b : p.bands) n += !b.label.empty();
    for (const Series& s : p.series) n += !s.label.empty();
    return n;
  }
  static int legend_columns(const Panel& p) { return p.columns_spanned; }

  void draw_series(const Series& s, const Panel& p) {
    pls_.col0(colour_index(s.colour));
    pls_.width(s.width);
    pls_.lsty(s.dashed ? 2 : 1);
    for (auto& [x, y] : drawable_runs(s, p.x_scale, p.y_scale)) {
      if (s.line && x.size() > 1) pls_.line(static_cast<PLINT>(x.size()), x.data(), y.data());
      if (s.marker != Marker::kNone)
        pls_.string(static_cast<PLINT>(x.size()), x.data(), y.data(), marker_glyph(s.marker));
    }
    pls_.lsty(1);
  }

  // The legend goes under the panel's axis title, so it never hides data.
  void draw_legend(const Panel& p, double viewport_height_px) {
    std::vector<PLINT> opt, text_colour, box_colour, box_pattern, line_colour, line_style,
        symbol_colour, symbol_number;
    std::vector<PLFLT> box_scale, box_width, line_width, symbol_scale;
    std::vector<const char*> text, symbol;
    auto add = [&](const std::string& label, PLINT o) {
      opt.push_back(o);
      text.push_back(label.c_str());
      text_colour.push_back(colour_index(Colour::kBlack));
    };
    for (const Band& b : p.bands) {
      if (b.label.empty()) continue;
      add(b.label, PL_LEGEND_COLOR_BOX);
      box_colour.push_back(band_index(b.colour));
      box_pattern.push_back(0);
      box_scale.push_back(0.8);
      box_width.push_back(1.0);
      line_colour.push_back(0), line_style.push_back(1), line_width.push_back(1.0);
      symbol_colour.push_back(0), symbol_scale.push_back(1.0), symbol_number.push_back(0);
      symbol.push_back("");
    }
    for (const Series& s : p.series) {
      if (s.label.empty()) continue;
      PLINT o = 0;
      if (s.line) o |= PL_LEGEND_LINE;
      if (s.marker != Marker::kNone) o |= PL_LEGEND_SYMBOL;
      add(s.label, o ? o : PL_LEGEND_NONE);
      box_colour.push_back(0), box_pattern.push_back(0), box_scale.push_back(0.0),
          box_width.push_back(0.0);
      line_colour.push_back(colour_index(s.colour));
      line_style.push_back(s.dashed ? 2 : 1);
      line_width.push_back(s.width);
      symbol_colour.push_back(colour_index(s.colour));
      symbol_scale.push_back(1.0);
      symbol_number.push_back(s.marker == Marker::kNone ? 0 : 1);
      symbol.push_back(marker_glyph(s.marker));
    }
    PLFLT width = 0, height = 0;
    pls_.width(1.0);
    const PLINT columns = legend_columns(p);
    const PLINT rows = (static_cast<PLINT>(opt.size()) + columns - 1) / columns;
    pls_.legend(&width, &height, PL_LEGEND_ROW_MAJOR,
                PL_POSITION_BOTTOM | PL_POSITION_OUTSIDE, 0.0,
                (kAxisBelowPx + 5.0) / viewport_height_px, 0.05 / p.columns_spanned, 0,
                colour_index(Colour::kGrey), 1, rows, columns, static_cast<PLINT>(opt.size()),
                opt.data(), 0.8, 0.7, 1.5, 0.0, text_colour.data(), text.data(),
                box_colour.data(), box_pattern.data(), box_scale.data(), box_width.data(),
                line_colour.data(), line_style.data(), line_width.data(),
                symbol_colour.data(), symbol_scale.data(), symbol_number.data(),
                symbol.data());
  }

  plstream& pls_;
  const Figure& fig_;
  std::pair<int, int> steps_{1, 1};  // decades per label on x and y (log axes)
};

std::mutex g_plplot_mutex;

}  // namespace

std::string render_svg(const Figure& figure) {
  check_figure(figure);
  std::lock_guard<std::mutex> lock(g_plplot_mutex);

  char* buffer = nullptr;
  size_t size = 0;
  FILE* out = open_memstream(&buffer, &size);
  if (!out) throw std::runtime_error("plot: cannot open a memory stream");
  g_plplot_problem.clear();
  {
    plstream pls;
    plsabort(&record_plplot_problem);
    pls.sdev("svg");
    pls.sfile(out);
    pls.spage(0, 0, figure.width_px, figure.height_px, 0, 0);
    pls.scmap0n(kBandBase + kPaletteSize);
    pls.scolbg(kBackground.r, kBackground.g, kBackground.b);
    for (int i = 0; i < kPaletteSize; ++i) {
      pls.scol0a(1 + i, kPalette[i].r, kPalette[i].g, kPalette[i].b, 1.0);
      pls.scol0a(kBandBase + i, kPalette[i].r, kPalette[i].g, kPalette[i].b, 0.18);
    }
    pls.scol0a(kGridColour, 225, 225, 225, 1.0);
    pls.init();
    pls.adv(0);
    pls.schr(0, kTextScale);
    if (!figure.title.empty()) {
      pls.vpor(0.0, 1.0, 1.0 - kTitleHeightPx / figure.height_px, 1.0);
      pls.wind(0.0, 1.0, 0.0, 1.0);
      pls.col0(colour_index(Colour::kBlack));
      pls.schr(0, 1.0);
      pls.ptex(0.5, 0.5, 1.0, 0.0, 0.5, figure.title.c_str());
      pls.schr(0, kTextScale);
    }
    PanelPainter painter(pls, figure);
    const std::vector<int> cells = first_cells(figure);
    for (size_t i = 0; i < figure.panels.size(); ++i) painter.draw(figure.panels[i], cells[i]);
  }  // ~plstream ends the page and flushes the document into `out`
  std::string svg(buffer ? buffer : "", size);
  std::free(buffer);
  if (!g_plplot_problem.empty()) throw std::runtime_error("plot: PLplot: " + g_plplot_problem);
  return svg;
}

}  // namespace ncinterp::plot
