// Grids of design points: lists and ranges of values, the product in a fixed order, one
// canonical text per point (the basis of its content-addressed key).
#include <gtest/gtest.h>

#include <stdexcept>

#include "design_point.h"

namespace ncinterp::sweep {
namespace {

std::string error_of(const std::string& text, double lo = 2, double hi = 32) {
  try {
    parse_values("--widths", text, lo, hi, "bits");
  } catch (const std::invalid_argument& e) {
    return e.what();
  }
  return "(no error)";
}

TEST(DesignPoint, ParsesListsRangesAndSteps) {
  EXPECT_EQ(parse_values("--widths", "8:11", 2, 32), (std::vector<double>{8, 9, 10, 11}));
  EXPECT_EQ(parse_values("--widths", "8,12,16", 2, 32), (std::vector<double>{8, 12, 16}));
  EXPECT_EQ(parse_values("--widths", "8:16:4,20", 2, 32), (std::vector<double>{8, 12, 16, 20}));
  EXPECT_EQ(parse_values("--blu", "0.001,0.01", 1e-6, 1), (std::vector<double>{0.001, 0.01}));
  EXPECT_EQ(parse_values("--clock-hz", "1e6,4e6", 1, 1e10), (std::vector<double>{1e6, 4e6}));
}

TEST(DesignPoint, RefusesWhatIsNotAListOfValuesInRange) {
  EXPECT_EQ(error_of("11:10"), "--widths: 11:10 runs backwards (LO must be <= HI)");
  EXPECT_EQ(error_of("8:40"), "--widths: 40 is outside 2..32 bits");
  EXPECT_EQ(error_of("1:4"), "--widths: 1 is outside 2..32 bits");
  EXPECT_EQ(error_of("8,x"), "--widths: '8,x' is not a list of numbers and ranges LO:HI[:STEP]");
  EXPECT_EQ(error_of("8,8"), "--widths: 8 is given twice");
  EXPECT_EQ(error_of("8:12:0"), "--widths: 8:12:0 needs a positive STEP");
  EXPECT_EQ(error_of(""), "--widths: no values");
  EXPECT_EQ(error_of("8.5:9"), "--widths: range bound '8.5' is not a whole number");
}

TEST(DesignPoint, TheGridIsEveryCombinationLastAxisFastest) {
  const std::vector<DesignPoint> g = expand_grid({{"IncWidth", {8, 9}}, {"blu_mm", {0.001, 0.01}}, {"X", {1}}});
  ASSERT_EQ(g.size(), 4u);
  EXPECT_EQ(point_text(g[0]), "IncWidth=8 X=1 blu_mm=0.001");
  EXPECT_EQ(point_text(g[1]), "IncWidth=8 X=1 blu_mm=0.01");
  EXPECT_EQ(point_text(g[2]), "IncWidth=9 X=1 blu_mm=0.001");
  EXPECT_EQ(point_text(g[3]), "IncWidth=9 X=1 blu_mm=0.01");
  EXPECT_EQ(point_value(g[3], "blu_mm", 0), 0.01);
  EXPECT_EQ(point_value(g[3], "PosWidth", 32), 32);
  EXPECT_EQ(value_text(1e6), "1000000");
  EXPECT_EQ(value_text(0.1 + 0.2), "0.3");  // one text for a value on every machine
}

}  // namespace
}  // namespace ncinterp::sweep
