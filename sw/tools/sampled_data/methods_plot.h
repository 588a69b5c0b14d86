// The SVG of `ncinterp methods --svg`: error against h on log axes, one curve per method.
#pragma once
#include <string>

#include "method_study.h"

namespace ncinterp::sampled {

// Top: the quarter-circle radial error / R of every method in double (L1: its end point
// error / L) with the paper's formulas dashed in the method's colour. Below: the drift of
// the error per turn, and the quarter error in fixed point (config.word_bits).
std::string methods_svg(const Study& study);

}  // namespace ncinterp::sampled
