// Design points of the sweep: a point is a map parameter name -> value, and a grid is a
// list of axes (one parameter, its values) whose cartesian product is the points.
// Idea: nothing here knows what a parameter means (point_run.h maps the names the tools
// understand: IncWidth, FeedWidth, PosWidth, blu_mm, clock_hz; any other name is an RTL
// parameter set with chparam). A new RTL parameter is one more axis, no new code. Values
// are kept as numbers and printed in one canonical form, so the same point always has the
// same text (and so the same content-addressed key) on every machine.
#pragma once
#include <map>
#include <string>
#include <vector>

namespace ncinterp::sweep {

using DesignPoint = std::map<std::string, double>;

struct GridAxis {
  std::string name;
  std::vector<double> values;
};

// Values of an option: a comma-separated list of numbers and integer ranges LO:HI or
// LO:HI:STEP ("8:16", "8,12,16", "24:32:4,48", "0.001,0.01", "1e6,4e6"). Throws
// std::invalid_argument naming the option for anything else, an empty list, a repeated
// value or a value outside [low, high].
std::vector<double> parse_values(const std::string& option, const std::string& text, double low, double high,
                                 const std::string& unit = "");

// Every combination, the last axis varying fastest; the axes' order is the grid's order.
std::vector<DesignPoint> expand_grid(const std::vector<GridAxis>& axes);

// The canonical text of a value ("%.15g": 16, 0.001, 1000000) and of a point
// ("IncWidth=16 blu_mm=0.001 ..." in name order).
std::string value_text(double v);
std::string point_text(const DesignPoint& p);

// The point's value of a parameter, or fallback when the point does not set it.
double point_value(const DesignPoint& p, const std::string& name, double fallback);

}  // namespace ncinterp::sweep
