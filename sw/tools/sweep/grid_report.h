// The tables and figure of a grid (`ncinterp sweep`, `--collect`): one row per design
// point, the Pareto front, the board recommendations, the per-point wall times, and the
// front's plot.
// Idea: the point table is the W sweep's table (sweep_table.h) with the point's parameters
// in front and the register ranges beside them, so one place still decides what a
// measured column holds. Wall times are kept out of the point table: they depend on the
// machine, the tables must not (a grid collected from any runner gives the same bytes).
#pragma once
#include <string>
#include <vector>

#include "pareto.h"
#include "plot/svg_figure.h"
#include "point_run.h"
#include "sweep_table.h"

namespace ncinterp::sweep {

// Columns: the axes, max_move_mm, pos_range_mm, feed_min_mm_min, feed_max_mm_min,
// feed_max_clock_mm_min, then sweep_table's (its "width" only when IncWidth is no axis).
Table grid_table(const std::vector<PointResult>& results, const std::vector<std::string>& axes);

// key, point, seconds: the wall time each point took where it ran (0: collected, never run).
Table timing_table(const std::vector<PointResult>& results);

// The front's rows of the grid table, in grid order, with the objectives' columns.
Table front_table(const Table& grid, const ParetoFront& front, const std::vector<std::string>& axes);

// board, logic_cells (capacity), point, ice40_logic_cells, hx1k_logic_cells,
// total_error_max_mm, tape_frames, rule.
Table recommendation_table(const std::vector<PointResult>& results, const std::vector<Recommendation>& recs);

// Area against total error and against tape length (without area: tape against error):
// every eligible point, the front joined.
plot::Figure pareto_figure(const std::vector<PointResult>& results, const ParetoFront& front, const std::string& title);

}  // namespace ncinterp::sweep
