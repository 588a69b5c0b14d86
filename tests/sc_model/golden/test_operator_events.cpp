// The operator's event list (operator_events.h): every name of --events becomes its press at
// its clock, sorted by time, an override with its P in 1/128; a bad P and anything else are
// refused naming the item; events_text() writes a list that parse_events() reads back to the
// same presses.
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

// P percent becomes P 128 / 100, rounded; the override's level is its clock's input and
// stays (FrameSource), the rapid override's too.
TEST(OperatorEvents, OverridesAreLevelsInUnitsOfAHundredAndTwentyEighth) {
  const auto events = parse_events("override=10@0.2s,rapid-override=25@0.1s,override=200@0.3s", 1e6);
  ASSERT_EQ(events.size(), 3u);
  EXPECT_EQ(events[0].kind, OperatorEvent::kRapidOverride);
  EXPECT_EQ(events[0].value, 32);
  EXPECT_EQ(events[1].kind, OperatorEvent::kFeedOverride);
  EXPECT_EQ(events[1].value, 13);  // 12.8
  EXPECT_EQ(events[2].value, 256);
  EXPECT_TRUE(has_override(events));
  EXPECT_FALSE(has_override(parse_events("hold@1s", 1e6)));
  InterpInputs in;
  EXPECT_EQ(in.feed_override, kOverrideOne);
  press(in, events[1]);
  EXPECT_EQ(in.feed_override, 13);
}

// The optional stop switch is a level: on or off from its clock (FrameSource), read back by
// events_text(); any other value is refused.
TEST(OperatorEvents, TheOptionalStopSwitchIsALevel) {
  const auto events = parse_events("optional-stop=off@0.5s,optional-stop=on@0s", 1e6);
  ASSERT_EQ(events.size(), 2u);
  EXPECT_EQ(events[0].kind, OperatorEvent::kOptionalStop);
  EXPECT_EQ(events[0].value, 1);
  EXPECT_EQ(events[1].value, 0);
  EXPECT_FALSE(has_override(events));
  EXPECT_EQ(events_text(events, 1e6), "optional-stop=on@0s,optional-stop=off@0.5s");
  InterpInputs in;
  EXPECT_FALSE(in.optional_stop);
  press(in, events[0]);
  EXPECT_TRUE(in.optional_stop);
  EXPECT_NE(refusal("optional-stop=yes@1s").find("needs =on or =off"), std::string::npos);
  EXPECT_NE(refusal("optional-stop@1s").find("needs =on or =off"), std::string::npos);
  EXPECT_EQ(last_event_cycle(events), 500001u);
}

TEST(OperatorEvents, BadPercentagesAndOtherNamesAreRefusedNamingTheItem) {
  EXPECT_NE(refusal("override=250@1s").find("'override=250@1s' needs a percentage from 0 to 200"),
            std::string::npos);
  EXPECT_NE(refusal("override=x@1s").find("needs a percentage"), std::string::npos);
  EXPECT_NE(refusal("override@1s").find("'override@1s' needs =P"), std::string::npos);
  EXPECT_NE(refusal("hold=5@1s").find("'hold=5@1s' takes no =value"), std::string::npos);
  EXPECT_NE(refusal("hold@1s,rapid-override=30@2s").find("'rapid-override=30@2s' needs 25, 50 or 100"),
            std::string::npos);
  EXPECT_NE(refusal("stop@1s").find("'stop@1s' is not an event"), std::string::npos);
  EXPECT_NE(refusal("estop").find("has no @T"), std::string::npos);
  EXPECT_NE(refusal("estop@-1s").find("needs a time in seconds"), std::string::npos);
  EXPECT_EQ(refusal(""), "accepted");
}

TEST(OperatorEvents, TheTextReadsBackToTheSamePresses) {
  for (double clock_hz : {1e6, 12e6, 20e3}) {
    const auto events = parse_events(
        "hold@0.123457s,start@0.2s,override=33.3@0.3s,rapid-override=50@0.4s,limit-x@1.5s,estop@2s,limit-y@3s",
        clock_hz);
    const auto again = parse_events(events_text(events, clock_hz), clock_hz);
    ASSERT_EQ(again.size(), events.size()) << events_text(events, clock_hz);
    for (size_t k = 0; k < events.size(); ++k) {
      EXPECT_EQ(again[k].kind, events[k].kind);
      EXPECT_EQ(again[k].cycle, events[k].cycle);
      EXPECT_EQ(again[k].value, events[k].value);
    }
  }
}

}  // namespace
}  // namespace ncinterp
