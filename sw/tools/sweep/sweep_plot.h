// The sweep's figure (`ncinterp sweep --svg`): area, Fmax and tape length against W on the
// top row; error, feed accuracy and simulated clocks against W below.
// Idea: only measured values are drawn; a width whose value is absent leaves a gap in its
// series (the CSV says why), and a panel with nothing measured says so in its title.
#pragma once
#include <string>
#include <vector>

#include "plot/svg_figure.h"
#include "sweep_row.h"

namespace ncinterp::sweep {

struct PlotContext {
  double blu_mm = 0.001;
  double tol_mm = 0.01;
  std::string title;
};

plot::Figure sweep_figure(const std::vector<SweepRow>& rows, const PlotContext& context);

}  // namespace ncinterp::sweep
