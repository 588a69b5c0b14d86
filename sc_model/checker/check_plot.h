// SVG plot of a check (`ncinterp check --svg`): the contour, the programmed chords and
// arcs, the pulse staircase, a panel zoomed on the worst point, the error along the path
// with the delta band, and the feed profile (each axis's speed against time); labels and a
// legend (drawn with sw/host/plot).
#pragma once
#include <string>

#include "check_report.h"

namespace ncinterp::checker {

// The SVG document. Needs the outcome's pulses (CheckSetup::keep_pulses).
std::string check_svg(const CheckOutcome& outcome, const ReportContext& context);

}  // namespace ncinterp::checker
