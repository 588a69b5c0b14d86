// The board's status lines (rtl/board/status_line.sv layout, sw/host/tape/board_link.def)
// parsed and worded by the host: a position field is two's complement in 20 bits.
#include <gtest/gtest.h>

#include "status_text.h"

namespace ncinterp::board {
namespace {

TEST(StatusText, ParsesBlockDoneAndErrorLines) {
  const auto b = parse_status_line("B 0000C 1E240 FFC18");
  ASSERT_TRUE(b);
  EXPECT_EQ(b->kind, 'B');
  EXPECT_EQ(b->block, 12u);
  EXPECT_EQ(b->x, 123456);
  EXPECT_EQ(b->y, -1000);
  EXPECT_EQ(describe(*b, 3), "block N12 ended at X123.456 Y-1.000 mm");
  const auto e = parse_status_line("E 00003 00039 00001");
  ASSERT_TRUE(e);
  EXPECT_EQ(e->code, 1);
  EXPECT_EQ(e->offset, 57u);
  EXPECT_NE(describe(*e, 3).find("block N3 at offset 57"), std::string::npos);
  EXPECT_NE(board_error_message(0x10).find("overflowed"), std::string::npos);
}

TEST(StatusText, RejectsOtherText) {
  for (const char* s : {"", "hello", "B 0000C 1E240 FFC1", "X 0000C 1E240 FFC18", "B 0000c 1E240 FFC18",
                        "B 0000C 1E240 FFC18 ", "E 00003 00039 00100", "B 0000C-1E240 FFC18"})
    EXPECT_FALSE(parse_status_line(s)) << s;
}

}  // namespace
}  // namespace ncinterp::board
