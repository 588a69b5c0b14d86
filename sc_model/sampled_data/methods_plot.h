// The SVG of `ncinterp methods --svg`: error against h on log axes, one panel per method.
#pragma once
#include <string>

#include "method_study.h"

namespace ncinterp::sampled {

// Per panel: the measured quarter-circle error / R in double (round-off limited points
// apart), in fixed point for each radius, the drift per turn, and the paper's formula.
std::string methods_svg(const Study& study);

}  // namespace ncinterp::sampled
