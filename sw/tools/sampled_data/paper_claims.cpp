// The paper's error claims (see paper_claims.h); section and wording in docs/sampled-data.md.
#include "paper_claims.h"

#include <cmath>
#include <limits>

namespace ncinterp::sampled {
namespace {

constexpr double kPi = 3.14159265358979323846;

double k1_exact(double h, double r) { return kPi * r / h * (std::sqrt(1 + h * h) - 1); }
double k1_small_h(double h, double r) { return 0.25 * kPi * h * r; }
double k4(double h, double r) { return 0.25 * h * r; }
double k5(double h, double r) { return 0.5 * h * h * r; }
double k7(double h, double r) { return 0.0625 * kPi * r * h * h; }

}  // namespace

const std::vector<PaperClaim>& paper_claims() {
  using Q = ClaimedQuantity;
  static const std::vector<PaperClaim> claims = {
      {Method::kK1, Q::kQuarterRadialError, "E_r = (pi R / h)(sqrt(1 + h^2) - 1)", 1, kPi / 2, k1_exact},
      {Method::kK1, Q::kQuarterRadialError, "E_r = 0.25 pi h R", 1, 0.25 * kPi, k1_small_h},
      {Method::kK2, Q::kStepError, "error on each step O(h^3)", 3, std::numeric_limits<double>::quiet_NaN(),
       nullptr},
      {Method::kK4, Q::kQuarterRadialError, "E_r = 0.25 h R", 1, 0.25, k4},
      {Method::kK5, Q::kQuarterRadialError, "E_r = 0.5 h^2 R", 2, 0.5, k5},
      {Method::kK7, Q::kQuarterRadialError, "E_r = 0.0625 pi R h^2", 2, 0.0625 * kPi, k7},
  };
  return claims;
}

const PaperClaim* quarter_claim(Method method) {
  const PaperClaim* found = nullptr;
  for (const PaperClaim& c : paper_claims())
    if (c.method == method && c.quantity == ClaimedQuantity::kQuarterRadialError) found = &c;
  return found;  // the last one listed: K1's small-h form
}

}  // namespace ncinterp::sampled
