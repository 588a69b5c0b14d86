// SVG plot of a check (see check_plot.h).
#include "check_plot.h"

#include <stdexcept>

namespace ncinterp::checker {

bool svg_available() { return false; }

std::string check_svg(const CheckOutcome&, const ReportContext&) {
  throw std::runtime_error("--svg needs the plot library (sw/plot), which this build does not have yet");
}

}  // namespace ncinterp::checker
