// The sweep's rows as a table of text cells: the CSV (`--csv`, one row per width) and the
// Markdown tables of docs/bit-widths.md (`--markdown`).
// Idea: one place decides what each column holds. A cell is a measured number or the
// reason it is absent; totals over the inputs are given only when every input was
// measured at that width (a total over some inputs would read as a total over all).
#pragma once
#include <string>
#include <vector>

#include "sweep_row.h"

namespace ncinterp::sweep {

struct Table {
  std::vector<std::string> header;
  std::vector<std::vector<std::string>> rows;
  size_t column(const std::string& name) const;  // index; throws std::out_of_range
};

// Columns: width, blocks, tape_frames, path_error_max_blu, total_error_max_mm, check,
// feed_error_worst, saturated_blocks, cycles, rtl_cosim, cells, flip_flops, ice40_luts,
// ice40_logic_cells, fmax_mhz (HX8K), hx1k_logic_cells, hx1k_fmax_mhz, then "blocks <input>" for every input.
Table sweep_table(const std::vector<SweepRow>& rows);

// RFC 4180 CSV: a cell with a comma, quote or line break is quoted.
std::string to_csv(const Table& table);
// A Markdown table of the named columns (all when empty).
std::string to_markdown(const Table& table, const std::vector<std::string>& columns = {});

}  // namespace ncinterp::sweep
