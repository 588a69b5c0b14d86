// The operator's event list (operator_events.h): every name of --events becomes its press at
// its clock, sorted by time; the names not built and anything else are refused naming the
// item; events_text() writes a list that parse_events() reads back to the same presses.
#include <gtest/gtest.h>

#include <stdexcept>
#include <string>

#include "operator_events.h"

namespace ncinterp {
namespace {

std::string refusal(const std::string& list) {
  try {
    parse_events(list, 1e6);
  } catch (const std::invalid_argument& e) {
    return e.what();
  }
  return "accepted";
}

TEST(OperatorEvents, EveryNameIsItsPressAtItsClockSortedByTime) {
  const auto events = parse_events("limit-y@0.5s,hold@0.1s,resume@0.2s,estop@0.4s,start@0.3s,limit-x@0.45s", 1e6);
  ASSERT_EQ(events.size(), 6u);
  const OperatorEvent::Kind kinds[] = {OperatorEvent::kHold,  OperatorEvent::kStart,  OperatorEvent::kStart,
                                       OperatorEvent::kEStop, OperatorEvent::kLimitX, OperatorEvent::kLimitY};
  const uint64_t cycles[] = {100001, 200001, 300001, 400001, 450001, 500001};
  for (size_t k = 0; k < events.size(); ++k) {
    EXPECT_EQ(events[k].kind, kinds[k]) << k;
    EXPECT_EQ(events[k].cycle, cycles[k]) << k;
  }
  ASSERT_NE(first_stop(events), nullptr);
  EXPECT_EQ(first_stop(events)->kind, OperatorEvent::kEStop);
  EXPECT_EQ(stop_error(OperatorEvent::kLimitX), TapeError::kLimitX);
  EXPECT_EQ(stop_error(OperatorEvent::kHold), TapeError::kNone);
  EXPECT_EQ(first_stop(parse_events("hold@1s,start@2s", 1e6)), nullptr);
}

TEST(OperatorEvents, NamesNotBuiltAndOthersAreRefusedNamingTheItem) {
  EXPECT_NE(refusal("override=50@1s").find("'override=50@1s' is not built yet"), std::string::npos);
  EXPECT_NE(refusal("hold@1s,rapid-override=25@2s").find("'rapid-override=25@2s' is not built yet"),
            std::string::npos);
  EXPECT_NE(refusal("stop@1s").find("'stop@1s' is not an event"), std::string::npos);
  EXPECT_NE(refusal("estop").find("has no @T"), std::string::npos);
  EXPECT_NE(refusal("estop@-1s").find("needs a time in seconds"), std::string::npos);
  EXPECT_EQ(refusal(""), "accepted");
}

TEST(OperatorEvents, TheTextReadsBackToTheSamePresses) {
  for (double clock_hz : {1e6, 12e6, 20e3}) {
    const auto events = parse_events("hold@0.123457s,start@0.2s,limit-x@1.5s,estop@2s,limit-y@3s", clock_hz);
    const auto again = parse_events(events_text(events, clock_hz), clock_hz);
    ASSERT_EQ(again.size(), events.size()) << events_text(events, clock_hz);
    for (size_t k = 0; k < events.size(); ++k) {
      EXPECT_EQ(again[k].kind, events[k].kind);
      EXPECT_EQ(again[k].cycle, events[k].cycle);
    }
  }
}

}  // namespace
}  // namespace ncinterp
