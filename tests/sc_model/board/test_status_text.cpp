// The board's status lines (rtl/board/status_line.sv layout, sw/host/tape/board_link.def)
// parsed, resolved and worded by the host: nibble digits 0x30 + n, N in 8 bits, the other
// fields in 12 (positions in two's complement), resolved by StatusTracker.
#include <gtest/gtest.h>

#include "status_text.h"

namespace ncinterp::board {
namespace {

tape::Program blocks(std::initializer_list<uint32_t> ns) {
  tape::Program p;
  for (const uint32_t n : ns) {
    tape::Block b;
    b.n = n;
    p.blocks.push_back(b);
  }
  return p;
}

TEST(StatusText, ParsesBlockDoneAndErrorLines) {
  // N 0x0C, X 0xE24 (3620), Y 0xC18 (-1000 in 12 bits).
  const auto b = parse_status_line("B0<>24<18");
  ASSERT_TRUE(b);
  EXPECT_EQ(b->kind, 'B');
  EXPECT_EQ(b->block, 12u);
  EXPECT_EQ(b->x, 0xE24u);
  EXPECT_EQ(b->y, 0xC18u);
  const auto e = parse_status_line("E03039001");
  ASSERT_TRUE(e);
  EXPECT_EQ(e->kind, 'E');
  EXPECT_EQ(e->block, 3u);
  EXPECT_EQ(e->offset, 57u);
  EXPECT_EQ(e->code, 1);
  EXPECT_NE(board_error_message(0x20).find("overflowed"), std::string::npos);
}

TEST(StatusText, RejectsOtherText) {
  for (const char* s : {"", "hello", "B0<>24<1", "X0<>24<18", "B0<>24<18 ", "B0c>24<18",
                        "E03039100", "B0<>2\x11<18", "B0<1>24?<18", "B 0000C 1E240 FFC18"})
    EXPECT_FALSE(parse_status_line(s)) << s;
}

TEST(StatusText, ResolvesPositionsByContinuity) {
  StatusTracker t(blocks({1}));
  // Up past +2047 and down past -2048 many times: each line moves less than half the range.
  int64_t x = 0, y = 0;
  for (int i = 0; i < 40; ++i) {
    x += 1500;
    y -= 2000;
    StatusLine l;
    l.kind = kStatusBlock;
    l.block = 1;
    l.x = static_cast<uint32_t>(x) & 0xfff;
    l.y = static_cast<uint32_t>(y) & 0xfff;
    const BoardStatus s = t.resolve(l, 100);
    EXPECT_EQ(s.x, x);
    EXPECT_EQ(s.y, y);
    EXPECT_EQ(s.block, 1u);
  }
  EXPECT_EQ(describe(t.resolve(StatusLine{kStatusDone, 1, static_cast<uint32_t>(x) & 0xfff,
                                          static_cast<uint32_t>(y) & 0xfff, 0, 0}, 100), 3),
            "program done after block N1 at X60.000 Y-80.000 mm");
}

TEST(StatusText, ResolvesBlocksInTapeOrderAndOffsetsBelowTheFramesSent) {
  // N 5, 261 (= 5 + 256), 300, 5 again: the low 8 bits name the next block with them.
  StatusTracker t(blocks({5, 261, 300, 5}));
  StatusLine l;
  l.kind = kStatusBlock;
  l.block = 5;
  EXPECT_EQ(t.resolve(l, 10).block, 5u);
  EXPECT_EQ(t.resolve(l, 10).block, 5u);  // still playing
  EXPECT_EQ(t.resolve(l, 20).block, 5u);
  l.block = 300 % 256;
  EXPECT_EQ(t.resolve(l, 30).block, 300u);  // N261 was too short to be seen
  l.block = 5;
  EXPECT_EQ(t.resolve(l, 40).block, 5u);
  // An error in a block the program does not have (its own N, never played): at or above
  // the last one named, the offset the last frame sent with its low 12 bits.
  StatusLine e;
  e.kind = kStatusError;
  e.block = 7;
  e.offset = 0x010;
  e.code = 1;
  const BoardStatus s = t.resolve(e, 0x30020);
  EXPECT_EQ(s.block, 7u);
  EXPECT_EQ(s.offset, 0x30010u);
  EXPECT_EQ(describe(s, 3), "error in block N7 at offset 196624: parity error (code 1)");
  EXPECT_EQ(describe(BoardStatus{kStatusBlock, 12, 123456, -1000, 0, 0}, 3),
            "block N12 playing, at X123.456 Y-1.000 mm");
}

}  // namespace
}  // namespace ncinterp::board
