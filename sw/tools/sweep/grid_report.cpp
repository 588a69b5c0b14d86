// Tables and figure of a grid (see grid_report.h).
#include "grid_report.h"

#include <algorithm>
#include <cstdio>

namespace ncinterp::sweep {
namespace {

std::string number(double v, const char* format) {
  char buf[64];
  std::snprintf(buf, sizeof buf, format, v);
  return buf;
}

const std::vector<std::string> kRangeColumns = {"max_move_mm", "pos_range_mm", "feed_min_mm_min", "feed_max_mm_min",
                                                "feed_max_clock_mm_min"};

bool has_axis(const std::vector<std::string>& axes, const std::string& name) {
  return std::find(axes.begin(), axes.end(), name) != axes.end();
}

}  // namespace

Table grid_table(const std::vector<PointResult>& results, const std::vector<std::string>& axes) {
  std::vector<SweepRow> rows;
  for (const PointResult& r : results) rows.push_back(r.row);
  const Table inner = sweep_table(rows);
  const size_t skip = has_axis(axes, kIncWidth) ? 1 : 0;  // inner's "width" column
  Table t;
  t.header = axes;
  t.header.insert(t.header.end(), kRangeColumns.begin(), kRangeColumns.end());
  t.header.insert(t.header.end(), inner.header.begin() + static_cast<long>(skip), inner.header.end());
  for (size_t i = 0; i < results.size(); ++i) {
    const PointResult& r = results[i];
    std::vector<std::string> c;
    for (const std::string& a : axes) c.push_back(r.point.count(a) ? value_text(r.point.at(a)) : "default");
    c.push_back(number(r.ranges.max_move_mm, "%.6g"));
    c.push_back(number(r.ranges.pos_range_mm, "%.6g"));
    c.push_back(number(r.ranges.feed_min_mm_min, "%.3g"));
    c.push_back(number(r.ranges.feed_max_mm_min, "%.6g"));
    c.push_back(number(r.ranges.feed_max_clock_mm_min, "%.6g"));
    c.insert(c.end(), inner.rows[i].begin() + static_cast<long>(skip), inner.rows[i].end());
    t.rows.push_back(std::move(c));
  }
  return t;
}

Table timing_table(const std::vector<PointResult>& results) {
  Table t;
  t.header = {"key", "point", "seconds"};
  for (const PointResult& r : results) t.rows.push_back({r.key, point_text(r.point), number(r.seconds, "%.2f")});
  return t;
}

Table front_table(const Table& grid, const ParetoFront& front, const std::vector<std::string>& axes) {
  Table t;
  std::vector<std::string> columns = axes;
  if (!has_axis(axes, kIncWidth)) columns.insert(columns.begin(), "width");
  for (const char* c : {"ice40_logic_cells", "hx1k_logic_cells", "fmax_mhz", "total_error_max_mm", "tape_frames",
                        "feed_error_worst", "max_move_mm", "pos_range_mm"})
    columns.push_back(c);
  std::vector<size_t> idx;
  for (const std::string& c : columns) idx.push_back(grid.column(c));
  t.header = columns;
  for (size_t m : front.members) {
    std::vector<std::string> row;
    for (size_t i : idx) row.push_back(grid.rows.at(m)[i]);
    t.rows.push_back(std::move(row));
  }
  return t;
}

Table recommendation_table(const std::vector<PointResult>& results, const std::vector<Recommendation>& recs) {
  Table t;
  t.header = {"board", "logic_cells", "point", "ice40_logic_cells", "hx1k_logic_cells", "total_error_max_mm",
              "tape_frames", "rule"};
  for (const Recommendation& r : recs) {
    std::vector<std::string> row = {r.board.name, number(r.board.logic_cells, "%.0f")};
    if (r.point) {
      const PointResult& p = results[*r.point];
      const SynthResult& s = p.row.synth;
      row.push_back(point_text(p.point));
      row.push_back(s.ice40_logic_cells.ok() ? number(*s.ice40_logic_cells.value, "%.0f") : s.ice40_logic_cells.reason);
      row.push_back(s.small_logic_cells.ok() ? number(*s.small_logic_cells.value, "%.0f") : s.small_logic_cells.reason);
      row.push_back(number(*p.row.worst(&InputResult::total_error_max_mm), "%.5f"));
      row.push_back(std::to_string(*p.row.total(&InputResult::frames)));
    } else {
      row.insert(row.end(), {"none", "", "", "", ""});
    }
    row.push_back(r.why);
    t.rows.push_back(std::move(row));
  }
  return t;
}

plot::Figure pareto_figure(const std::vector<PointResult>& results, const ParetoFront& front, const std::string& title) {
  const bool area = !front.objectives.empty() && front.objectives.front() == "ice40_logic_cells";
  auto value = [&](const PointResult& r, const std::string& what) -> double {
    if (what == "area") return *r.row.synth.ice40_logic_cells.value;
    if (what == "error") return *r.row.worst(&InputResult::total_error_max_mm);
    return static_cast<double>(*r.row.total(&InputResult::frames));
  };
  // Eligible points: those the front was chosen from (every objective measured, passed).
  std::vector<size_t> eligible;
  for (size_t i = 0; i < results.size(); ++i) {
    const PointResult& r = results[i];
    bool ok = r.row.missing_input().empty() && r.row.worst(&InputResult::total_error_max_mm) &&
              (!area || r.row.synth.ice40_logic_cells.ok());
    for (const InputResult& in : r.row.inputs) ok &= in.violations == 0;
    if (ok) eligible.push_back(i);
  }
  struct Axes {
    std::string x, y, x_label, y_label;
  };
  std::vector<Axes> panels;
  if (area) {
    panels = {{"area", "error", "iCE40 logic cells (HX8K placement)", "total error, mm"},
              {"area", "tape", "iCE40 logic cells (HX8K placement)", "tape length, frames"}};
  } else {
    panels = {{"tape", "error", "tape length, frames", "total error, mm"}};
  }
  plot::Figure f;
  f.title = title;
  f.columns = static_cast<int>(panels.size());
  f.width_px = 600 * f.columns;
  f.height_px = 500;
  for (const Axes& a : panels) {
    plot::Panel p;
    p.title = area ? "Pareto front over area, total error and tape length" : "Pareto front over tape and error (no area measured)";
    p.x_label = a.x_label;
    p.y_label = a.y_label;
    if (a.y == "tape" || a.x == "tape") (a.y == "tape" ? p.y_scale : p.x_scale) = plot::Scale::kLog10;
    plot::Series all{"design points", {}, {}, plot::Colour::kGrey, false, false, 1.0, plot::Marker::kDot};
    for (size_t i : eligible) all.x.push_back(value(results[i], a.x)), all.y.push_back(value(results[i], a.y));
    plot::Series front_series{"Pareto front", {}, {}, plot::Colour::kRed, false, false, 1.0, plot::Marker::kCircle};
    std::vector<size_t> members = front.members;
    std::sort(members.begin(), members.end(),
              [&](size_t i, size_t j) { return value(results[i], a.x) < value(results[j], a.x); });
    for (size_t i : members) front_series.x.push_back(value(results[i], a.x)), front_series.y.push_back(value(results[i], a.y));
    if (all.x.empty()) p.title = "no point passed with every objective measured";
    p.series = {all, front_series};
    f.panels.push_back(std::move(p));
  }
  return f;
}

}  // namespace ncinterp::sweep
