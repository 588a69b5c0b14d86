// What paper 003 claims about the error of its methods, as data the measurements are
// compared with (methods_report.cpp). Nothing here is fitted or adjusted: these are the
// paper's formulas, transcribed.
// Idea: each claim is a law c h^p R for a measured quantity; the paper's formula is kept
// as written (K1's exact form included), with its small-h order and constant beside it.
#pragma once
#include <vector>

#include "method.h"

namespace ncinterp::sampled {

enum class ClaimedQuantity {
  kQuarterRadialError,  // largest radial error over a quarter circle
  kStepError,           // error made in one period ("on each step")
};

struct PaperClaim {
  Method method;
  ClaimedQuantity quantity;
  const char* formula;  // as the paper writes it
  double order;         // p, for small h
  double constant;      // c of c h^p R for small h; NaN: the paper states only the order
  double (*value)(double h, double radius);  // the formula; nullptr when only the order is stated
};

const std::vector<PaperClaim>& paper_claims();

// The paper's headline quarter-circle formula for a method (K1's small-h form), or
// nullptr when the paper gives none.
const PaperClaim* quarter_claim(Method method);

}  // namespace ncinterp::sampled
