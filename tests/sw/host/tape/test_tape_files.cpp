// Tape files: .tape frames vs plain text, the 7-bit check, atomic writing, and every
// bundled example tape parses.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "scratch_dir_test.h"
#include "tape.h"

namespace fs = std::filesystem;

namespace ncinterp::tape {
namespace {

class TapeFileTest : public ncinterp::test::ScratchDirTest {
 protected:
  static Program square() {
    Program p;
    p.blocks = {{1, Motion::kLine, 1000, 0, 0, 0, 6000},
                {2, Motion::kLine, 0, 1000, 0, 0, 6000},
                {3, Motion::kLine, -1000, 0, 0, 0, 6000},
                {4, Motion::kLine, 0, -1000, 0, 0, 6000}};
    return p;
  }
};

TEST_F(TapeFileTest, TapeFileHoldsFramesWithParity) {
  write_tape_file(path("sq.tape"), square(), Format{});
  std::ifstream in(path("sq.tape"), std::ios::binary);
  const std::vector<uint8_t> raw((std::istreambuf_iterator<char>(in)), {});
  const std::vector<uint8_t> frames = load_frames(path("sq.tape"));
  EXPECT_EQ(raw, frames);
  EXPECT_EQ(frames, add_parity(format_program(square(), Format{})));
  EXPECT_EQ(parse_frames(frames, Format{}).blocks.size(), 4u);
  EXPECT_EQ(files().size(), 1u);
}

TEST_F(TapeFileTest, PlainTextGetsParityOnLoad) {
  write_tape_file(path("sq.nc"), square(), Format{});
  const std::vector<uint8_t> frames = load_frames(path("sq.nc"));
  EXPECT_EQ(frames, add_parity(format_program(square(), Format{})));
  std::ifstream in(path("sq.nc"));
  std::string first;
  std::getline(in, first);
  EXPECT_EQ(first, "%");  // plain text on disk, readable by any G-code tool
}

TEST_F(TapeFileTest, EightBitByteInPlainTextIsAClearError) {
  write("bad.nc", "%\nN1 G01 X1.000 F1.000 (caf\xC3\xA9)\nM02\n%\n");
  try {
    load_frames(path("bad.nc"));
    FAIL();
  } catch (const std::runtime_error& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find(path("bad.nc") + ": offset 27: byte 0xC3"), std::string::npos) << what;
  }
}

TEST_F(TapeFileTest, MissingFileNamesTheFile) {
  try {
    load_frames(path("none.tape"));
    FAIL();
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("none.tape"), std::string::npos);
  }
}

TEST_F(TapeFileTest, FailedWriteLeavesNothingAndKeepsTheOldTape) {
  Program bad = square();
  bad.blocks[2].dx = 1 << 20;  // too wide for the 16-bit increment register
  EXPECT_THROW(write_tape_file(path("new.tape"), bad, Format{}), std::invalid_argument);
  EXPECT_EQ(files().size(), 0u);

  write_tape_file(path("old.tape"), square(), Format{});
  const std::vector<uint8_t> before = load_frames(path("old.tape"));
  EXPECT_THROW(write_tape_file(path("old.tape"), bad, Format{}), std::invalid_argument);
  EXPECT_EQ(load_frames(path("old.tape")), before);
  EXPECT_EQ(files().size(), 1u);

  EXPECT_THROW(write_tape_file(path("no_dir/x.tape"), square(), Format{}), std::runtime_error);
  EXPECT_EQ(files().size(), 1u);
}

TEST(TapeExamples, EveryBundledTapeParses) {
  int tapes = 0;
  for (const auto& entry : fs::directory_iterator(NCINTERP_EXAMPLES_DIR)) {
    const std::string ext = entry.path().extension().string();
    if (!entry.is_regular_file() || (ext != ".tape" && ext != ".nc")) continue;
    SCOPED_TRACE(entry.path().string());
    ++tapes;
    const Program p = parse_frames(load_frames(entry.path().string()), Format{});
    EXPECT_FALSE(p.blocks.empty());
  }
  EXPECT_GT(tapes, 0) << "no example tapes in " << NCINTERP_EXAMPLES_DIR;
}

}  // namespace
}  // namespace ncinterp::tape
