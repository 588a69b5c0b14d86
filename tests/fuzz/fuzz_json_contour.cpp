// JSON contour reader fuzzer: any text goes to the JSON contour reader (sw/host/firststage/
// inputs/json_contour.cpp: lines, arcs, cubics, tables); a refusal must be a one-line
// InputError "FILE:LINE: what", an accepted contour must go through the whole first stage
// (contour_pipeline.h).
#include "contour_pipeline.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  return ncinterp::fuzz::fuzz_reader(data, size, "fuzz.json", ncinterp::firststage::InputKind::kJson);
}
