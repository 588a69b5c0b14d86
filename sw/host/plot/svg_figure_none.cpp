// render_svg() of a build without PLplot (CMake option NCINTERP_PLOT=OFF, the first build of
// scripts/demo.sh): every command still runs, and an SVG output fails with one line that
// says how to get it.
#include <stdexcept>

#include "svg_figure.h"

namespace ncinterp::plot {

std::string render_svg(const Figure&) {
  throw std::runtime_error(
      "this ncinterp was built without PLplot, so it draws no SVG (scripts/setup.sh installs "
      "libplplot-dev and builds with it)");
}

}  // namespace ncinterp::plot
