// Airfoil .dat reader fuzzer: any text goes to the airfoil reader (Selig and Lednicer,
// sw/host/firststage/inputs/airfoil.cpp) at a 100 mm chord; a refusal must be a one-line
// InputError, an accepted contour (a parametric spline) must go through the whole first
// stage (contour_pipeline.h).
#include "contour_pipeline.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  return ncinterp::fuzz::fuzz_reader(data, size, "fuzz.dat", ncinterp::firststage::InputKind::kAirfoil);
}
