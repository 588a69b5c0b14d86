// --widths LO:HI: the accepted forms and one clear error for each wrong one.
#include <gtest/gtest.h>

#include <stdexcept>

#include "width_range.h"

namespace ncinterp::sweep {
namespace {

TEST(WidthRange, ParsesARangeAndASingleWidth) {
  const WidthRange r = parse_width_range("8:32");
  EXPECT_EQ(r.low, 8u);
  EXPECT_EQ(r.high, 32u);
  EXPECT_EQ(r.count(), 25u);
  const WidthRange one = parse_width_range("12");
  EXPECT_EQ(one.low, 12u);
  EXPECT_EQ(one.high, 12u);
  EXPECT_EQ(one.count(), 1u);
  EXPECT_EQ(parse_width_range("2:2").low, 2u);
}

std::string error_of(const std::string& text) {
  try {
    parse_width_range(text);
  } catch (const std::invalid_argument& e) {
    return e.what();
  }
  return "";
}

TEST(WidthRange, RejectsMalformedTextWithAReason) {
  for (const char* bad : {"", ":", "8:", ":32", "8-32", "a:b", "8:32:40", " 8:32", "8.5:9", "-4:8", "0008:9"})
    EXPECT_NE(error_of(bad).find("is not LO:HI"), std::string::npos) << "'" << bad << "': " << error_of(bad);
}

TEST(WidthRange, RejectsWidthsOutsideWhatTheModelsTakeAndBackwardRanges) {
  EXPECT_NE(error_of("1:8").find("1 is outside 2..32 bits"), std::string::npos) << error_of("1:8");
  EXPECT_NE(error_of("8:33").find("33 is outside 2..32 bits"), std::string::npos) << error_of("8:33");
  EXPECT_NE(error_of("12:10").find("runs backwards"), std::string::npos) << error_of("12:10");
}

}  // namespace
}  // namespace ncinterp::sweep
