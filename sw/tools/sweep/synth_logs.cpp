// Parsers of yosys and nextpnr-ice40 logs (see synth_logs.h).
#include "synth_logs.h"

#include <regex>
#include <sstream>
#include <vector>

namespace ncinterp::sweep {
namespace {

bool starts_with(const std::string& s, const char* prefix) { return s.rfind(prefix, 0) == 0; }

std::string trim(const std::string& s) {
  const size_t a = s.find_first_not_of(" \t\r");
  if (a == std::string::npos) return "";
  return s.substr(a, s.find_last_not_of(" \t\r") - a + 1);
}

std::vector<std::string> lines_of(const std::string& text) {
  std::vector<std::string> lines;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);) lines.push_back(line);
  return lines;
}

}  // namespace

uint64_t YosysStat::count(const std::string& type) const {
  const auto it = cell_types.find(type);
  return it == cell_types.end() ? 0 : it->second;
}

uint64_t YosysStat::flip_flops() const {
  uint64_t n = 0;
  for (const auto& [type, count] : cell_types)
    if (starts_with(type, "$_DFF") || starts_with(type, "$_SDFF") || starts_with(type, "$_ALDFF") ||
        starts_with(type, "SB_DFF"))
      n += count;
  return n;
}

std::optional<YosysStat> parse_yosys_stat(const std::string& log) {
  const std::vector<std::string> lines = lines_of(log);
  static const std::regex cells_re(R"(^\s+Number of cells:\s+(\d+)\s*$)");
  static const std::regex type_re(R"(^\s+(\S+)\s+(\d+)\s*$)");
  size_t last = lines.size();
  std::smatch m;
  for (size_t i = 0; i < lines.size(); ++i)
    if (std::regex_match(lines[i], m, cells_re)) last = i;
  if (last == lines.size()) return std::nullopt;
  YosysStat stat;
  std::regex_match(lines[last], m, cells_re);
  stat.cells = std::stoull(m[1]);
  // The cell types follow, one per line, up to the first line of another shape.
  for (size_t i = last + 1; i < lines.size() && std::regex_match(lines[i], m, type_re); ++i)
    stat.cell_types[m[1]] += std::stoull(m[2]);
  return stat;
}

NextpnrReport parse_nextpnr_log(const std::string& log) {
  static const std::regex fmax_re(R"(Max frequency for clock '[^']*': ([0-9.]+) MHz)");
  static const std::regex lc_re(R"(ICESTORM_LC:\s+(\d+)/\s*(\d+))");
  NextpnrReport r;
  std::smatch m;
  for (const std::string& line : lines_of(log)) {
    if (std::regex_search(line, m, fmax_re)) r.fmax_mhz = std::stod(m[1]);
    if (std::regex_search(line, m, lc_re)) {
      r.logic_cells = std::stoull(m[1]);
      r.logic_cells_available = std::stoull(m[2]);
    }
  }
  return r;
}

std::string first_error_line(const std::string& log) {
  for (const std::string& line : lines_of(log))
    for (const char* mark : {"ERROR:", "%Error", "error:", "CMake Error"})
      if (line.find(mark) != std::string::npos) return trim(line);
  return "";
}

}  // namespace ncinterp::sweep
