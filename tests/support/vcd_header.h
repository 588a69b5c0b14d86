// Minimal VCD reading for tests: full signal names (scopes joined with '.') and widths,
// and the timestamps. Enough to compare two tracers' files, not a VCD library.
#pragma once
#include <cstdint>
#include <map>
#include <string>
#include <vector>

namespace ncinterp::test {

// Full name ("SystemC.interp.interp_top.clk_i") -> width.
std::map<std::string, int> vcd_signals(const std::string& path);
// Every "#<time>" in order.
std::vector<uint64_t> vcd_times(const std::string& path);

}  // namespace ncinterp::test
