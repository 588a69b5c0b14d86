// Sweep rows -> table, CSV, Markdown (see sweep_table.h).
#include "sweep_table.h"

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <stdexcept>

namespace ncinterp::sweep {
namespace {

std::string number(double v, const char* format) {
  char buf[64];
  std::snprintf(buf, sizeof buf, format, v);
  return buf;
}

std::string cell(const Measured& m, const char* format) { return m.value ? number(*m.value, format) : m.reason; }

// A total or worst value over the inputs, or "refused" when an input could not be taped
// at this width (the reason is given once, in the check column).
constexpr const char* kRefused = "refused";

std::string total(const SweepRow& row, uint64_t InputResult::*field) {
  const std::optional<uint64_t> v = row.total(field);
  return v ? std::to_string(*v) : kRefused;
}

std::string worst(const SweepRow& row, double InputResult::*field, const char* format) {
  const std::optional<double> v = row.worst(field);
  return v ? number(*v, format) : kRefused;
}

std::string check_cell(const SweepRow& row) {
  const std::string missing = row.missing_input();
  if (!missing.empty()) return missing;  // "input: reason"
  for (const InputResult& in : row.inputs)
    if (in.violations)
      return "FAIL " + std::filesystem::path(in.input).filename().string() + ": " + std::to_string(in.violations) +
             " violation(s), first " + in.first_violation;
  return "pass";
}

std::string csv_cell(const std::string& s) {
  if (s.find_first_of(",\"\r\n") == std::string::npos) return s;
  std::string q = "\"";
  for (char c : s) q += c == '"' ? std::string("\"\"") : std::string(1, c);
  return q + "\"";
}

std::string markdown_cell(const std::string& s) {
  std::string out;
  for (char c : s) out += c == '|' ? std::string("\\|") : c == '\n' ? std::string(" ") : std::string(1, c);
  return out;
}

}  // namespace

size_t Table::column(const std::string& name) const {
  const auto it = std::find(header.begin(), header.end(), name);
  if (it == header.end()) throw std::out_of_range("no column '" + name + "'");
  return static_cast<size_t>(it - header.begin());
}

Table sweep_table(const std::vector<SweepRow>& rows) {
  Table t;
  t.header = {"width", "blocks", "tape_frames", "path_error_max_blu", "total_error_max_mm", "check",
              "feed_error_worst", "saturated_blocks", "cycles", "rtl_cosim", "cells", "flip_flops",
              "ice40_luts", "ice40_logic_cells", "fmax_mhz", "hx1k_logic_cells", "hx1k_fmax_mhz"};
  if (!rows.empty())
    for (const InputResult& in : rows.front().inputs)
      t.header.push_back("blocks " + std::filesystem::path(in.input).filename().string());
  for (const SweepRow& r : rows) {
    std::vector<std::string> c = {
        std::to_string(r.width),
        total(r, &InputResult::blocks),
        total(r, &InputResult::frames),
        worst(r, &InputResult::path_error_max_blu, "%.4f"),
        worst(r, &InputResult::total_error_max_mm, "%.5f"),
        check_cell(r),
        worst(r, &InputResult::feed_error_worst, "%.3e"),
        total(r, &InputResult::saturated_blocks),
        total(r, &InputResult::cycles),
        r.rtl.summary,
        cell(r.synth.cells, "%.0f"),
        cell(r.synth.flip_flops, "%.0f"),
        cell(r.synth.ice40_luts, "%.0f"),
        cell(r.synth.ice40_logic_cells, "%.0f"),
        cell(r.synth.fmax_mhz, "%.2f"),
        cell(r.synth.small_logic_cells, "%.0f"),
        cell(r.synth.small_fmax_mhz, "%.2f")};
    for (const InputResult& in : r.inputs) c.push_back(in.measured() ? std::to_string(in.blocks) : kRefused);
    t.rows.push_back(std::move(c));
  }
  return t;
}

std::string to_csv(const Table& t) {
  std::string s;
  auto line = [&s](const std::vector<std::string>& cells) {
    for (size_t i = 0; i < cells.size(); ++i) s += (i ? "," : "") + csv_cell(cells[i]);
    s += "\n";
  };
  line(t.header);
  for (const auto& r : t.rows) line(r);
  return s;
}

std::string to_markdown(const Table& t, const std::vector<std::string>& columns) {
  std::vector<size_t> idx;
  if (columns.empty())
    for (size_t i = 0; i < t.header.size(); ++i) idx.push_back(i);
  else
    for (const std::string& c : columns) idx.push_back(t.column(c));
  std::string s = "|";
  for (size_t i : idx) s += " " + markdown_cell(t.header[i]) + " |";
  s += "\n|";
  for (size_t k = 0; k < idx.size(); ++k) s += "---|";
  s += "\n";
  for (const auto& r : t.rows) {
    s += "|";
    for (size_t i : idx) s += " " + markdown_cell(r[i]) + " |";
    s += "\n";
  }
  return s;
}

}  // namespace ncinterp::sweep
