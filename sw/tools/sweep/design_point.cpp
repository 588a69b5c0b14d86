// Grids of design points (see design_point.h).
#include "design_point.h"

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <sstream>
#include <stdexcept>

namespace ncinterp::sweep {
namespace {

double parse_number(const std::string& option, const std::string& item, const std::string& whole) {
  char* end = nullptr;
  const double v = std::strtod(item.c_str(), &end);
  if (item.empty() || end != item.c_str() + item.size() || !std::isfinite(v))
    throw std::invalid_argument(option + ": '" + whole + "' is not a list of numbers and ranges LO:HI[:STEP]");
  return v;
}

long long parse_integer(const std::string& option, const std::string& item, const std::string& whole) {
  const double v = parse_number(option, item, whole);
  if (v != std::floor(v) || std::fabs(v) > 1e15)
    throw std::invalid_argument(option + ": range bound '" + item + "' is not a whole number");
  return static_cast<long long>(v);
}

}  // namespace

std::vector<double> parse_values(const std::string& option, const std::string& text, double low, double high,
                                 const std::string& unit) {
  auto check_range = [&](double v) {
    if (v < low || v > high)
      throw std::invalid_argument(option + ": " + value_text(v) + " is outside " + value_text(low) + ".." +
                                  value_text(high) + (unit.empty() ? "" : " " + unit));
  };
  std::vector<double> out;
  std::istringstream in(text);
  for (std::string item; std::getline(in, item, ',');) {
    const size_t colon = item.find(':');
    if (colon == std::string::npos) {
      out.push_back(parse_number(option, item, text));
      continue;
    }
    const size_t colon2 = item.find(':', colon + 1);
    const long long lo = parse_integer(option, item.substr(0, colon), text);
    const long long hi = parse_integer(option, item.substr(colon + 1, colon2 - colon - 1), text);
    const long long step = colon2 == std::string::npos ? 1 : parse_integer(option, item.substr(colon2 + 1), text);
    if (lo > hi) throw std::invalid_argument(option + ": " + item + " runs backwards (LO must be <= HI)");
    if (step <= 0) throw std::invalid_argument(option + ": " + item + " needs a positive STEP");
    for (long long bound : {lo, hi}) check_range(static_cast<double>(bound));  // before a huge range is made
    for (long long v = lo; v <= hi; v += step) out.push_back(static_cast<double>(v));
  }
  if (out.empty()) throw std::invalid_argument(option + ": no values");
  for (size_t i = 0; i < out.size(); ++i) {
    check_range(out[i]);
    for (size_t j = 0; j < i; ++j)
      if (out[j] == out[i]) throw std::invalid_argument(option + ": " + value_text(out[i]) + " is given twice");
  }
  return out;
}

std::vector<DesignPoint> expand_grid(const std::vector<GridAxis>& axes) {
  std::vector<DesignPoint> points = {DesignPoint{}};
  for (const GridAxis& axis : axes) {
    std::vector<DesignPoint> next;
    for (const DesignPoint& p : points)
      for (double v : axis.values) {
        DesignPoint q = p;
        q[axis.name] = v;
        next.push_back(std::move(q));
      }
    points = std::move(next);
  }
  return points;
}

std::string value_text(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.15g", v);
  return buf;
}

std::string point_text(const DesignPoint& p) {
  std::string s;
  for (const auto& [name, value] : p) s += (s.empty() ? "" : " ") + name + "=" + value_text(value);
  return s;
}

double point_value(const DesignPoint& p, const std::string& name, double fallback) {
  const auto it = p.find(name);
  return it == p.end() ? fallback : it->second;
}

}  // namespace ncinterp::sweep
