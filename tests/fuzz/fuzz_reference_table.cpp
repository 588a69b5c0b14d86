// Reference-point table fuzzer: the input is a table as a designer writes it, numbers
// separated by white space, "x0 h y0 y1 y2 ..."; it becomes a JSON contour of one table
// segment starting at (x0, y0) (docs/inputs.md) and goes through the JSON reader and the
// whole first stage (contour_pipeline.h).
// Idea: the JSON target rarely builds a well-formed table by mutation; here every input
// with at least two numbers is one, so the fuzzer works on the table's numbers (spacing,
// differences, huge and tiny values) instead of the JSON syntax. Inputs with a token
// that is not a number are skipped.
#include <cstdlib>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>
#include <vector>

#include "contour_pipeline.h"
#include "fuzz_check.h"
#include "inputs/contour_inputs.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  if (size > 4096) return -1;
  std::istringstream in(std::string(reinterpret_cast<const char*>(data), size));
  std::vector<double> numbers;
  for (std::string token; in >> token;) {
    char* end = nullptr;
    const double v = std::strtod(token.c_str(), &end);
    if (end != token.c_str() + token.size()) return 0;
    numbers.push_back(v);
  }
  if (numbers.size() < 3) return 0;
  const std::vector<double> y(numbers.begin() + 2, numbers.end());
  const nlohmann::json doc = {
      {"start", {numbers[0], y[0]}},
      {"segments", {{{"type", "table"}, {"x0", numbers[0]}, {"h", numbers[1]}, {"y", y}}}}};
  const std::string text = doc.dump(2);  // NaN and infinity become null: the reader refuses
  return ncinterp::fuzz::fuzz_reader(reinterpret_cast<const uint8_t*>(text.data()), text.size(),
                                     "fuzz.json", ncinterp::firststage::InputKind::kJson);
}
