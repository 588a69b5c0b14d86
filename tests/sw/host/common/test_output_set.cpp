// OutputSet: the outputs of a run are checked when reserved (before any work), an output
// that is an input is refused (also through a symlink), and they appear all together on
// commit or not at all.
#include <gtest/gtest.h>

#include <filesystem>
#include <stdexcept>

#include "output_set.h"
#include "scratch_dir_test.h"

namespace fs = std::filesystem;

namespace {

using OutputSetTest = ncinterp::test::ScratchDirTest;

TEST_F(OutputSetTest, AllOutputsAppearOnCommit) {
  ncinterp::OutputSet set;
  auto* a = set.add(path("a.tape"));
  auto* b = set.add(path("b.json"));
  EXPECT_EQ(set.add(""), nullptr);  // an option not given
  ncinterp::OutputSet::write(a, "A");
  ncinterp::OutputSet::write(b, "B");
  EXPECT_FALSE(fs::exists(path("a.tape")));
  set.commit();
  EXPECT_EQ(files(), (std::vector<std::string>{"a.tape", "b.json"}));
  EXPECT_EQ(slurp(path("b.json")), "B");
}

TEST_F(OutputSetTest, NoCommitLeavesNoOutput) {
  {
    ncinterp::OutputSet set;
    ncinterp::OutputSet::write(set.add(path("a.tape")), "A");
  }
  EXPECT_TRUE(files().empty());
}

TEST_F(OutputSetTest, BadSecondOutputFailsAtOnceAndLeavesNothing) {
  try {
    ncinterp::OutputSet set;
    set.add(path("a.tape"));
    set.add(path("nodir/r.json"));
    FAIL() << "expected an error";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("nodir/r.json"), std::string::npos) << e.what();
  }
  EXPECT_TRUE(files().empty());
}

TEST_F(OutputSetTest, OutputThatIsAnInputIsRefused) {
  write("part.nc", "G01 X1 Y1\n");
  ncinterp::OutputSet set;
  set.input(path("part.nc"));
  EXPECT_THROW(set.add(path("part.nc")), std::runtime_error);
  fs::create_symlink("part.nc", path("alias.nc"));
  EXPECT_THROW(set.add(path("alias.nc")), std::runtime_error);
  EXPECT_EQ(slurp(path("part.nc")), "G01 X1 Y1\n");
}

TEST_F(OutputSetTest, InputReachedThroughASymlinkIsRefused) {
  write("part.nc", "G01 X1 Y1\n");
  fs::create_symlink("part.nc", path("in.nc"));
  ncinterp::OutputSet set;
  set.input(path("in.nc"));
  EXPECT_THROW(set.add(path("part.nc")), std::runtime_error);
}

TEST_F(OutputSetTest, SameOutputTwiceIsRefused) {
  ncinterp::OutputSet set;
  set.add(path("x.svg"));
  EXPECT_THROW(set.add(path("x.svg")), std::runtime_error);
}

TEST_F(OutputSetTest, DiscardedOutputIsNotWritten) {
  ncinterp::OutputSet set;
  auto* vcd = set.add(path("w.vcd"));
  set.add(path("r.json"));
  set.discard(vcd);
  set.commit();
  EXPECT_EQ(files(), std::vector<std::string>{"r.json"});
}

}  // namespace
