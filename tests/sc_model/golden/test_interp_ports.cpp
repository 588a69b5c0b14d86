// Tests of the interpolator's shared contract (interp_ports.h, interp_outputs.def): every
// output takes part in the comparison the scoreboard uses, the port kinds convert to and
// from SystemC signals, and the tape format and the configuration convert both ways.
#include <gtest/gtest.h>

#include <set>
#include <string>

#include "interp_ports.h"

namespace ncinterp {
namespace {

// A value of `kind` other than the default, for a field of that kind.
template <class Kind>
typename Kind::Value changed() {
  return static_cast<typename Kind::Value>(1);
}

TEST(InterpPorts, EveryOutputTakesPartInEquality) {
  std::set<std::string> names;
#define INTERP_OUTPUT(name, kind, width)                                       \
  {                                                                            \
    InterpOutputs a, b;                                                        \
    b.name = changed<Port##kind>();                                            \
    EXPECT_NE(a, b) << #name " is not compared";                               \
    EXPECT_TRUE(names.insert(#name).second) << #name " is listed twice";       \
  }
#include "interp_outputs.def"
#undef INTERP_OUTPUT
  EXPECT_EQ(names.size(), 17u);  // the ports of rtl/interp_top.sv's output list
  EXPECT_EQ(InterpOutputs{}, InterpOutputs{});
}

TEST(InterpPorts, PositionIsMaskedOnTheSignalAndSignExtendedBack) {
  for (unsigned width : {12u, 32u}) {
    for (int64_t v : {int64_t{0}, int64_t{1}, int64_t{-1}, int64_t{-2048}, int64_t{2047}}) {
      const uint32_t s = PortPosition::to_signal(v, width);
      if (width < 32) EXPECT_EQ(s >> width, 0u) << v;
      EXPECT_EQ(PortPosition::from_signal(s, width), v) << v << " in " << width << " bits";
    }
  }
  EXPECT_EQ(PortPosition::to_signal(-1, 12), 0xfffu);
  EXPECT_EQ(PortPosition::from_rtl(uint32_t{0xffffffffu}), -1);
}

TEST(InterpPorts, ErrorCodeFitsItsPort) {
  // error_code_o is kTapeErrorBits wide: every code of tape_errors.def fits.
#define TAPE_ERROR(name, code, message) EXPECT_LT((code), 1u << kTapeErrorBits) << #name;
#include "tape_errors.def"
#undef TAPE_ERROR
  EXPECT_EQ(PortCode::from_signal(PortCode::to_signal(12, 4), 4), 12);
}

TEST(InterpPorts, ConfigurationFollowsTheTapeFormat) {
  tape::Format f;
  f.frac_digits = 4;
  f.feed_frac_digits = 2;
  f.inc_width = 20;
  f.feed_width = 24;
  f.seq_width = 12;
  const InterpConfig cfg = interp_config(2e6, f);
  EXPECT_EQ(cfg.frac_digits, 4u);
  EXPECT_EQ(cfg.inc_width, 20u);
  EXPECT_EQ(cfg.feed_modulus, InterpConfig::feed_modulus_for(2e6, 2));
  const tape::Format back = tape_format_of(cfg);
  EXPECT_EQ(back.frac_digits, f.frac_digits);
  EXPECT_EQ(back.feed_frac_digits, f.feed_frac_digits);
  EXPECT_EQ(back.inc_width, f.inc_width);
  EXPECT_EQ(back.feed_width, f.feed_width);
  EXPECT_EQ(back.seq_width, f.seq_width);
  // The default format is the default machine (the verilated RTL's parameters).
  EXPECT_TRUE(interp_config(1e6).same_parameters(InterpConfig{}));
  EXPECT_FALSE(cfg.same_parameters(InterpConfig{}));
}

TEST(InterpPorts, EngineNames) {
  EXPECT_STREQ(engine_name(EngineKind::kGolden), "golden");
  EXPECT_STREQ(engine_name(EngineKind::kRtl), "rtl");
}

}  // namespace
}  // namespace ncinterp
