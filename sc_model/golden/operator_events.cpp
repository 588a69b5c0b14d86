// Parses the operator's event list (operator_events.h).
#include "operator_events.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <iterator>
#include <stdexcept>

namespace ncinterp {

namespace {

// The names of --events and their presses; "resume" is cycle start's other name (events_text()
// writes the first name of a kind).
// An override's name is followed by =P, the optional stop switch's by =on or =off.
struct EventName {
  const char* name;
  OperatorEvent::Kind kind;
};
constexpr EventName kEventNames[] = {
    {"hold", OperatorEvent::kHold},    {"start", OperatorEvent::kStart},    {"resume", OperatorEvent::kStart},
    {"estop", OperatorEvent::kEStop},  {"limit-x", OperatorEvent::kLimitX}, {"limit-y", OperatorEvent::kLimitY},
    {"override", OperatorEvent::kFeedOverride}, {"rapid-override", OperatorEvent::kRapidOverride},
    {"optional-stop", OperatorEvent::kOptionalStop},
};
constexpr const char* kNameList =
    "hold, resume, start, override=P, rapid-override=P, estop, limit-x, limit-y, "
    "optional-stop=on|off";

bool is_override(OperatorEvent::Kind kind) {
  return kind == OperatorEvent::kFeedOverride || kind == OperatorEvent::kRapidOverride;
}

// P of "override=P" or "rapid-override=P" in units of 1 / kOverrideOne; `bad` builds the error.
template <class Bad>
uint16_t parse_override(OperatorEvent::Kind kind, const std::string& percent, const Bad& bad) {
  char* stop = nullptr;
  const double p = std::strtod(percent.c_str(), &stop);
  if (percent.empty() || *stop != '\0' || !(p >= 0) || !(p <= 200))
    throw bad("needs a percentage from 0 to 200 after =, e.g. override=50@1.5s");
  if (kind == OperatorEvent::kRapidOverride && p != 25 && p != 50 && p != 100)
    throw bad("needs 25, 50 or 100 after = (the rapid override's steps, ISO's and grbl's)");
  return override_units(p);
}

// The kinds that set a level (=value) rather than press a button.
bool has_value(OperatorEvent::Kind kind) {
  return is_override(kind) || kind == OperatorEvent::kOptionalStop;
}

// The value after '=' of a level's name; `bad` builds the error.
template <class Bad>
uint16_t parse_value(OperatorEvent::Kind kind, const std::string& value, const Bad& bad) {
  if (kind != OperatorEvent::kOptionalStop) return parse_override(kind, value, bad);
  if (value != "on" && value != "off") throw bad("needs =on or =off (the optional stop switch)");
  return value == "on";
}

}  // namespace

std::vector<OperatorEvent> parse_events(const std::string& list, double clock_hz) {
  std::vector<OperatorEvent> events;
  size_t pos = 0;
  while (pos <= list.size() && !list.empty()) {
    const size_t end = std::min(list.find(',', pos), list.size());
    const std::string item = list.substr(pos, end - pos);
    const size_t at = item.find('@');
    const auto bad = [&](const std::string& why) {
      return std::invalid_argument("--events: '" + item + "' " + why);
    };
    if (at == std::string::npos) throw bad("has no @T (e.g. hold@0.8s)");
    const std::string word = item.substr(0, at), when = item.substr(at + 1);
    const size_t eq = word.find('=');
    const std::string name = word.substr(0, eq);
    char* stop = nullptr;
    const double t = std::strtod(when.c_str(), &stop);
    if (when.empty() || stop == when.c_str() || std::string(stop) != "s" || !(t >= 0) || !(t <= 1e6))
      throw bad("needs a time in seconds from 0 to 10^6, e.g. @1.5s");
    const auto known = std::find_if(std::begin(kEventNames), std::end(kEventNames),
                                    [&](const EventName& n) { return name == n.name; });
    if (known == std::end(kEventNames)) throw bad(std::string("is not an event (") + kNameList + ")");
    if (has_value(known->kind) != (eq != std::string::npos))
      throw bad(known->kind == OperatorEvent::kOptionalStop ? "needs =on or =off (optional-stop=on@0s)"
                : is_override(known->kind) ? "needs =P, a percentage (e.g. override=50@1.5s)"
                                           : "takes no =value");
    const uint16_t value =
        has_value(known->kind) ? parse_value(known->kind, word.substr(eq + 1), bad) : 0;
    events.push_back({static_cast<uint64_t>(std::llround(t * clock_hz)) + 1, known->kind, value});
    pos = end + 1;
  }
  sort_by_clock(events);
  return events;
}

void sort_by_clock(std::vector<OperatorEvent>& events) {
  std::stable_sort(events.begin(), events.end(),
                   [](const OperatorEvent& a, const OperatorEvent& b) { return a.cycle < b.cycle; });
}

std::string events_text(const std::vector<OperatorEvent>& events, double clock_hz) {
  std::string text;
  for (const OperatorEvent& e : events) {
    const auto named = std::find_if(std::begin(kEventNames), std::end(kEventNames),
                                    [&](const EventName& n) { return n.kind == e.kind; });
    char value[64] = "", at[64];
    if (is_override(e.kind)) std::snprintf(value, sizeof value, "=%.17g", override_percent(e.value));
    if (e.kind == OperatorEvent::kOptionalStop) std::snprintf(value, sizeof value, e.value ? "=on" : "=off");
    std::snprintf(at, sizeof at, "@%.17gs", static_cast<double>(e.cycle - 1) / clock_hz);
    text += (text.empty() ? "" : ",") + std::string(named->name) + value + at;
  }
  return text;
}

bool has_override(const std::vector<OperatorEvent>& events) {
  return std::any_of(events.begin(), events.end(), [](const OperatorEvent& e) { return is_override(e.kind); });
}

const OperatorEvent* first_stop(const std::vector<OperatorEvent>& events) {
  for (const OperatorEvent& e : events)
    if (stop_error(e.kind) != TapeError::kNone) return &e;
  return nullptr;
}

TapeError stop_error(OperatorEvent::Kind kind) {
  switch (kind) {
    case OperatorEvent::kEStop: return TapeError::kEmergencyStop;
    case OperatorEvent::kLimitX: return TapeError::kLimitX;
    case OperatorEvent::kLimitY: return TapeError::kLimitY;
    default: return TapeError::kNone;
  }
}

}  // namespace ncinterp
