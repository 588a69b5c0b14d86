// Every bad-tape rule gives the decoder's error code, the right block N and the offset of
// the offending frame. Each case marks the offending frame with '^' in the text (the
// marker is removed before parsing), so offsets are never counted by hand.
#include <gtest/gtest.h>

#include <set>
#include <string>

using namespace std::string_literals;

#include "tape.h"

namespace ncinterp::tape {
namespace {

struct BadCase {
  const char* name;
  std::string marked_text;  // '^' right before the offending frame (or at the end)
  unsigned code;
  uint32_t block;
};

const std::string kHead = "%\nG17 G21 G91 G93\nN1 G01 X1.000 Y2.000 F10.000\n";

std::vector<BadCase> bad_cases() {
  return {
      {"unknown_letter", kHead + "N2 G01 ^Q1.000\nM02\n%\n", 2, 2},
      {"lower_case", kHead + "N2 G01 ^x1.000\nM02\n%\n", 2, 2},
      {"tab", kHead + "N2 G01^\tX1.000\nM02\n%\n", 2, 2},
      {"close_paren", kHead + "N2 ^)\nM02\n%\n", 2, 2},
      {"unknown_after_bad_word", kHead + "N2 ^X1.00Q\nM02\n%\n", 3, 2},  // word first
      {"too_few_fraction_digits", kHead + "N2 G01 ^X1.00 Y1.000\nM02\n%\n", 3, 2},
      {"too_many_fraction_digits", kHead + "N2 G01 X1.000^5\nM02\n%\n", 3, 2},
      {"no_point", kHead + "N2 G01 ^X1\nM02\n%\n", 3, 2},
      {"point_first", kHead + "N2 G01 X^.500\nM02\n%\n", 3, 2},
      {"two_points", kHead + "N2 G01 X1.0^.0\nM02\n%\n", 3, 2},
      {"late_sign", kHead + "N2 G01 X1^-.000\nM02\n%\n", 3, 2},
      {"two_signs", kHead + "N2 G01 X-^-1.000\nM02\n%\n", 3, 2},
      {"sign_on_feed", kHead + "N2 G01 X1.000 F^-1.000\nM02\n%\n", 3, 2},
      {"point_in_N", kHead + "N2^.5 G01\nM02\n%\n", 3, 1},
      {"empty_G", kHead + "N2 ^G X1.000\nM02\n%\n", 3, 2},
      {"digit_without_letter", kHead + "N2 G01 (c)^5\nM02\n%\n", 3, 2},
      {"x_too_wide", kHead + "N2 G01 X65.53^6\nM02\n%\n", 4, 2},
      {"x_too_wide_leading_zeros", kHead + "N2 G01 X-000099.99^9\nM02\n%\n", 4, 2},
      {"g_too_wide", kHead + "N2 G10^0\nM02\n%\n", 4, 2},
      {"n_too_wide", kHead + "N104857^6 G01\nM02\n%\n", 4, 1},
      {"second_N", kHead + "N2 G01 X1.000 ^N3\nM02\n%\n", 5, 2},
      {"percent_inside_block", kHead + "N2 G01 X1.000^%\n", 5, 2},
      {"unsupported_G", kHead + "N2 ^G33 X1.000\nM02\n%\n", 6, 2},
      {"unsupported_M", kHead + "N2 ^M04\nM02\n%\n", 6, 2},
      {"second_M_word", kHead + "N2 M03 ^M05\nM02\n%\n", 6, 2},
      {"second_M_word_end", kHead + "N2 G01 X1.000 F1.000 M05 ^M02\n%\n", 6, 2},
      {"unsupported_setup_G", "%\n^G20 G91\nM02\n%\n", 6, 0},
      {"truncated_no_end", kHead + "N2 G01 X1.000 F1.000\n^", 7, 2},
      {"truncated_mid_word", kHead + "N2 G01 X1.0^", 7, 2},
      {"truncated_in_comment", kHead + "(no end^", 7, 1},
      {"percent_before_end", kHead + "^%\n", 7, 1},
      {"empty_tape", "^", 7, 0},
      {"leader_only", "\0\0\0^"s, 7, 0},
      {"block_after_end", kHead + "M02\n^N5 G01 X1.000\n%\n", 8, 1},
      {"comment_after_end", kHead + "M30\n%\n^(late)\n", 8, 1},
      {"missing_feed", "%\nN1 G01 X1.000^\nM02\n%\n", 9, 1},
      {"feed_zero", "%\nN1 G01 X1.000 F0.000^\nM02\n%\n", 9, 1},
      {"zero_move_needs_feed", "%\nN4 G01^\nM02\n%\n", 9, 4},
  };
}

std::vector<uint8_t> unmark(const std::string& marked, uint64_t& offset) {
  const auto at = marked.find('^');
  offset = at;
  std::string text = marked;
  text.erase(at, 1);
  return add_parity(text);
}

TEST(TapeErrors, EachRuleGivesCodeBlockAndOffset) {
  for (const BadCase& c : bad_cases()) {
    SCOPED_TRACE(c.name);
    uint64_t offset = 0;
    const std::vector<uint8_t> frames = unmark(c.marked_text, offset);
    try {
      parse_frames(frames, Format{});
      ADD_FAILURE() << "accepted a bad tape";
    } catch (const TapeFormatError& e) {
      EXPECT_EQ(e.info().code, c.code) << e.what();
      EXPECT_EQ(e.info().block, c.block) << e.what();
      EXPECT_EQ(e.info().offset, offset) << e.what();
      const std::string expect_prefix =
          "block N" + std::to_string(c.block) + ", offset " + std::to_string(offset) + ": ";
      EXPECT_EQ(std::string(e.what()).rfind(expect_prefix, 0), 0u) << e.what();
    }
  }
}

// The M words played (Format::misc_functions), and refused by the interpolator built
// without them (the iCEstick's), at the M word, naming the configuration.
TEST(TapeErrors, MWordsAreRefusedWithoutTheMiscellaneousFunctions) {
  const std::string text = kHead + "N2 G01 X1.000 F1.000 M03\nN3 M00\nN4 G01 Y1.000 M05\nM02\n%\n";
  const Program p = parse_frames(add_parity(text), Format{});
  ASSERT_EQ(p.blocks.size(), 4u);  // N1 of kHead first
  EXPECT_TRUE(p.blocks[1].tool_on);
  EXPECT_TRUE(p.blocks[2].still && p.blocks[2].stop && p.blocks[2].motion == Motion::kRapid);
  EXPECT_TRUE(p.blocks[3].tool_off);
  EXPECT_EQ(format_program(p, Format{}).find("N3 M00\n") != std::string::npos, true);
  Format without;
  without.misc_functions = false;
  try {
    parse_frames(add_parity(text), without);
    ADD_FAILURE() << "accepted M03 without the miscellaneous functions";
  } catch (const TapeFormatError& e) {
    EXPECT_EQ(e.info().code, static_cast<unsigned>(TapeError::kUnsupportedCode)) << e.what();
    EXPECT_EQ(e.info().offset, text.find("M03")) << e.what();
    EXPECT_NE(std::string(e.what()).find("MiscFunctions = 0"), std::string::npos) << e.what();
  }
}

TEST(TapeErrors, ParityErrorAnywhere) {
  // A flipped bit 7 at every frame of a good tape, including the leader and after the end:
  // always error 1 at that frame, block = the last N committed before it.
  const std::string text = "\0%\nG17 G21 G91 G93\nN1 G01 X1.000 F1.000\nN22 Y-2.000\nM02\n%\n"s;
  const std::vector<uint8_t> good = add_parity(text);
  ASSERT_NO_THROW(parse_frames(good, Format{}));
  for (size_t k = 0; k < good.size(); ++k) {
    std::vector<uint8_t> bad = good;
    bad[k] ^= 0x80;
    const ParseResult r = parse_frames_partial(bad, Format{});
    ASSERT_TRUE(r.error) << k;
    EXPECT_EQ(r.error->code, 1u);
    EXPECT_EQ(r.error->offset, k);
    // "N22" is committed when its word ends at the 'Y' (spaces do not end a number), but
    // a parity error on that very 'Y' comes first: the frame is not read.
    const size_t n22_committed = text.find("Y-2");
    const size_t n1_committed = text.find("G01");
    const uint32_t expect = k > n22_committed ? 22 : k > n1_committed ? 1 : 0;
    EXPECT_EQ(r.error->block, expect) << "frame " << k;
  }
}

// Each arc rule of docs/circle-dda.md section 2, in the decoder's order, at the arc's LF.
TEST(TapeErrors, BadArcsNameTheirRuleBlockAndLf) {
  const struct {
    const char* words;
    unsigned code;
  } cases[] = {
      {"G02 X1.000 Y1.000 I0.000 J0.000", 12},   // zero radius
      {"G03 X1.000 Y1.000 I1.000 J0.000", 10},   // (-1, 0) ccw to (0, 1): three quadrants
      {"G03 X0.000 Y0.000 I1.000 J0.000", 10},   // no move: a full circle
      {"G03 X1.000 Y-2.100 I1.000 J0.000", 11},  // (-1, 0) to (0, -2.1) mm: off its circle
      {"G02 X65.535 Y-46.341 I-0.001 J-46.341", 4},  // end beyond the register
  };
  for (const auto& c : cases) {
    const std::string block = std::string("N2 ") + c.words + "\n";
    const std::string text = kHead + block + "M02\n%\n";
    const ParseResult r = parse_frames_partial(add_parity(text), Format{});
    ASSERT_TRUE(r.error) << c.words;
    EXPECT_EQ(r.error->code, c.code) << c.words << ": " << r.error->message;
    EXPECT_EQ(r.error->block, 2u) << c.words;
    EXPECT_EQ(r.error->offset, kHead.size() + block.size() - 1) << c.words;
  }
  // A good full quadrant passes.
  const std::string good = kHead + "N2 G03 X-1.000 Y1.000 I-1.000 J0.000\nM02\n%\n";
  EXPECT_NO_THROW(parse_frames(add_parity(good), Format{}));
}

TEST(TapeErrors, TapeWithoutPercentSaysSoNotThatM02IsMissing) {
  // M02 is there, but without '%' the whole tape is leader.
  const ParseResult r = parse_frames_partial(add_parity("N1 G01 X1.000 F1.000\nN2 M02\n"), Format{});
  ASSERT_TRUE(r.error.has_value());
  EXPECT_EQ(r.error->code, 7u);
  EXPECT_NE(r.error->message.find("no '%'"), std::string::npos) << r.error->message;
  EXPECT_EQ(r.error->message.find("before M02"), std::string::npos) << r.error->message;
}

TEST(TapeErrors, PartialParseKeepsTheGoodBlocks) {
  const std::string text = kHead + "N2 G01 X3.000 F1.000\nN3 X1.000 Q\nM02\n%\n";
  const ParseResult r = parse_frames_partial(add_parity(text), Format{});
  ASSERT_TRUE(r.error);
  EXPECT_EQ(r.error->block, 3u);
  ASSERT_EQ(r.program.blocks.size(), 2u);
  EXPECT_EQ(r.program.blocks[1].dx, 3000);
}

TEST(TapeErrors, WidthsFollowTheFormat) {
  Format f;
  f.inc_width = 8;  // |d| <= 255 BLU
  EXPECT_NO_THROW(parse_frames(add_parity("%\nN1 G01 X-0.255 F1.000\nM02\n%\n"), f));
  EXPECT_THROW(parse_frames(add_parity("%\nN1 G01 X-0.256 F1.000\nM02\n%\n"), f),
               TapeFormatError);
  f.frac_digits = 0;
  EXPECT_NO_THROW(parse_frames(add_parity("%\nN1 G01 X-255. F1.000\nM02\n%\n"), f));
  EXPECT_THROW(parse_frames(add_parity("%\nN1 G01 X-255 F1.000\nM02\n%\n"), f), TapeFormatError);
}

// The codes of tape_errors.def: 0 .. n-1 without a gap, each with its own message.
TEST(TapeErrors, CodesAreDenseWithOwnMessages) {
  std::set<std::string> messages;
  unsigned expected = 0;
#define TAPE_ERROR(name, code, message)                                                   \
  EXPECT_EQ(static_cast<unsigned>(TapeError::k##name), expected++) << #name;              \
  EXPECT_STREQ(tape_error_message(TapeError::k##name), message);                          \
  EXPECT_TRUE(messages.insert(message).second) << #name " shares its message";
#include "tape_errors.def"
#undef TAPE_ERROR
  EXPECT_STREQ(tape_error_message(static_cast<TapeError>(expected)), "unknown error code");
  EXPECT_LT(expected - 1, 1u << kTapeErrorBits);
  EXPECT_GE(expected - 1, 1u << (kTapeErrorBits - 1));  // no bit to spare
}

}  // namespace
}  // namespace ncinterp::tape
