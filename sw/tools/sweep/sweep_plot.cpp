// The sweep's figure from its rows (see sweep_plot.h).
#include "sweep_plot.h"

#include <algorithm>
#include <filesystem>
#include <functional>
#include <optional>

namespace ncinterp::sweep {
namespace {

using plot::Colour;
using plot::Marker;
using plot::Panel;
using plot::Series;

const Colour kPalette[] = {Colour::kBlue,  Colour::kRed,   Colour::kGreen, Colour::kOrange, Colour::kPurple,
                           Colour::kBrown, Colour::kCyan,  Colour::kGrey,  Colour::kBlack};

// A series of the widths where `get` has a value.
Series series(const std::vector<SweepRow>& rows, std::string label, Colour colour,
              const std::function<std::optional<double>(const SweepRow&)>& get) {
  Series s;
  s.label = std::move(label);
  s.colour = colour;
  s.marker = Marker::kDot;
  for (const SweepRow& r : rows)
    if (const std::optional<double> v = get(r)) s.x.push_back(r.width), s.y.push_back(*v);
  return s;
}

std::optional<double> value(const Measured& m) { return m.value; }

// Worst (largest magnitude) of a per-input value, when every input was measured.
std::function<std::optional<double>(const SweepRow&)> worst(double InputResult::*field, double scale) {
  return [field, scale](const SweepRow& r) -> std::optional<double> {
    const std::optional<double> w = r.worst(field);
    if (!w) return std::nullopt;
    return *w * scale;
  };
}

Panel panel(std::string title, std::string y_label, std::vector<Series> all) {
  Panel p;
  p.title = std::move(title);
  p.x_label = "increment register width W (bits)";
  p.y_label = std::move(y_label);
  for (Series& s : all)
    if (!s.x.empty()) p.series.push_back(std::move(s));
  if (p.series.empty()) p.title += " (not measured)";
  return p;
}

}  // namespace

plot::Figure sweep_figure(const std::vector<SweepRow>& rows, const PlotContext& ctx) {
  plot::Figure f;
  f.title = ctx.title;
  f.columns = 3;
  f.rows = 2;
  f.width_px = 1500;
  f.height_px = 900;

  // Area on a log axis: flip-flops and gates differ tenfold.
  Panel area = panel("Area (yosys)", "cells",
                     {series(rows, "generic cells", Colour::kBlue, [](const SweepRow& r) { return value(r.synth.cells); }),
                      series(rows, "flip-flops", Colour::kRed, [](const SweepRow& r) { return value(r.synth.flip_flops); }),
                      series(rows, "iCE40 LUT4", Colour::kGreen, [](const SweepRow& r) { return value(r.synth.ice40_luts); }),
                      series(rows, "HX8K logic cells (placed harness)", Colour::kOrange,
                             [](const SweepRow& r) { return value(r.synth.ice40_logic_cells); })});
  area.y_scale = plot::Scale::kLog10;
  f.panels.push_back(std::move(area));

  Panel fmax = panel("Fmax after routing, HX8K (nextpnr-ice40)", "MHz",
                     {series(rows, "", Colour::kPurple, [](const SweepRow& r) { return value(r.synth.fmax_mhz); })});
  f.panels.push_back(std::move(fmax));

  // Tape length: every input's blocks, on a log axis (narrow registers multiply them).
  std::vector<Series> tape;
  if (!rows.empty()) {
    for (size_t i = 0; i < rows.front().inputs.size(); ++i) {
      const std::string name = std::filesystem::path(rows.front().inputs[i].input).filename().string();
      tape.push_back(series(rows, name, kPalette[i % std::size(kPalette)], [i](const SweepRow& r) -> std::optional<double> {
        if (i >= r.inputs.size() || !r.inputs[i].measured()) return std::nullopt;
        return static_cast<double>(r.inputs[i].blocks);
      }));
    }
  }
  Panel tape_panel = panel("Tape length", "blocks", std::move(tape));
  tape_panel.y_scale = plot::Scale::kLog10;
  f.panels.push_back(std::move(tape_panel));

  // Errors in micrometres, both against the tolerance.
  const double um_per_blu = ctx.blu_mm * 1000.0;
  std::vector<Series> errors = {
      series(rows, "interpolator (to the blocks)", Colour::kBlue,
             worst(&InputResult::path_error_max_blu, um_per_blu)),
      series(rows, "total (to the contour)", Colour::kRed,
             worst(&InputResult::total_error_max_mm, 1000.0))};
  if (!errors[0].x.empty() || !errors[1].x.empty()) {
    Series tol;  // drawn only beside measured errors
    tol.label = "tolerance delta";
    tol.colour = Colour::kGrey;
    tol.dashed = true;
    for (const SweepRow& r : rows) tol.x.push_back(r.width), tol.y.push_back(ctx.tol_mm * 1000.0);
    errors.push_back(std::move(tol));
  }
  Panel error = panel("Max error (checker)", "micrometres", std::move(errors));
  error.y_range = plot::Range{0.0, 1.2 * ctx.tol_mm * 1000.0};  // the tolerance line inside the frame
  f.panels.push_back(std::move(error));

  f.panels.push_back(panel("Feed: worst block time vs 1/F", "relative error (%)",
                           {series(rows, "", Colour::kBrown,
                                   worst(&InputResult::feed_error_worst, 100.0))}));

  Panel cycles = panel("Simulated clocks", "clocks to the end of program",
                       {series(rows, "", Colour::kBlack, [](const SweepRow& r) -> std::optional<double> {
                         const std::optional<uint64_t> sum = r.total(&InputResult::cycles);
                         if (!sum) return std::nullopt;
                         return static_cast<double>(*sum);
                       })});
  if (!cycles.series.empty()) {  // from 0, so the axis has labels
    const std::vector<double>& y = cycles.series.front().y;
    cycles.y_range = plot::Range{0.0, 1.1 * *std::max_element(y.begin(), y.end())};
  }
  f.panels.push_back(std::move(cycles));
  return f;
}

}  // namespace ncinterp::sweep
