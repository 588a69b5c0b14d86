// Reading the numbers the sweep needs out of yosys and nextpnr-ice40 logs.
// Idea: the tools print human-readable reports, not data; these parsers take exactly the
// lines the sweep relies on (yosys `stat`, nextpnr's utilisation and "Max frequency for
// clock") and return nothing rather than guess when a line is missing, so a changed log
// format shows up as a missing value with its reason, never as a wrong number.
#pragma once
#include <cstdint>
#include <map>
#include <optional>
#include <string>

namespace ncinterp::sweep {

// The last `stat` of a yosys log: for a hierarchical design that is the "design hierarchy"
// section, whose counts are the whole design's.
struct YosysStat {
  uint64_t cells = 0;
  std::map<std::string, uint64_t> cell_types;  // type -> count
  // Flip-flops: generic $_DFF*/$_SDFF*/$_ALDFF*/$_DFFSR* cells, or iCE40 SB_DFF* cells.
  uint64_t flip_flops() const;
  uint64_t count(const std::string& type) const;
};
std::optional<YosysStat> parse_yosys_stat(const std::string& log);

struct NextpnrReport {
  std::optional<double> fmax_mhz;       // the last "Max frequency for clock" (after routing)
  std::optional<uint64_t> logic_cells;  // ICESTORM_LC used ...
  std::optional<uint64_t> logic_cells_available;  // ... of the device's
};
NextpnrReport parse_nextpnr_log(const std::string& log);

// The first line of a log that reports an error, trimmed: "ERROR: ..." of yosys (also as
// "file:line: ERROR: ...") and nextpnr, "%Error..." of Verilator, "error: ..." of a
// compiler, "CMake Error ...".
// "" when there is none.
std::string first_error_line(const std::string& log);

}  // namespace ncinterp::sweep
