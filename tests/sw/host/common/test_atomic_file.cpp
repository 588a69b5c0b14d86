// AtomicOutputFile: the target appears only on commit, complete; nothing is left behind
// when the writer gives up; an existing target survives a failed rewrite.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>

#include "atomic_file.h"
#include "scratch_dir_test.h"

namespace fs = std::filesystem;

namespace {

using AtomicFileTest = ncinterp::test::ScratchDirTest;

TEST_F(AtomicFileTest, CommitCreatesTheTargetWithTheContent) {
  {
    ncinterp::AtomicOutputFile f(path("out.txt"));
    f.stream() << "hello\n";
    EXPECT_FALSE(fs::exists(path("out.txt")));  // not visible before commit
    f.commit();
  }
  EXPECT_EQ(slurp(path("out.txt")), "hello\n");
  EXPECT_EQ(files().size(), 1u);  // no temporary left
}

TEST_F(AtomicFileTest, NoCommitLeavesNothing) {
  {
    ncinterp::AtomicOutputFile f(path("out.vcd"));
    f.stream() << "partial";
    EXPECT_TRUE(fs::exists(f.temp_path()));
  }
  EXPECT_EQ(files().size(), 0u);
}

TEST_F(AtomicFileTest, ExceptionKeepsTheOldTarget) {
  ncinterp::write_file_atomically(path("report.json"), std::string_view("old"));
  try {
    ncinterp::AtomicOutputFile f(path("report.json"));
    f.stream() << "new but incomplete";
    throw std::runtime_error("simulated failure");
  } catch (const std::runtime_error&) {
  }
  EXPECT_EQ(slurp(path("report.json")), "old");
  EXPECT_EQ(files().size(), 1u);
}

TEST_F(AtomicFileTest, TemporaryKeepsTheExtensionAndDirectory) {
  ncinterp::AtomicOutputFile f(path("wave.vcd"));
  const fs::path t(f.temp_path());
  EXPECT_EQ(t.extension(), ".vcd");
  EXPECT_EQ(t.parent_path(), dir_);
  EXPECT_NE(t.filename(), "wave.vcd");
}

TEST_F(AtomicFileTest, ToolWritingByNameIsCommitted) {
  // The VCD tracers open the temporary by name themselves.
  ncinterp::AtomicOutputFile f(path("w.vcd"));
  { std::ofstream(f.temp_path()) << "$date"; }
  f.commit();
  EXPECT_EQ(slurp(path("w.vcd")), "$date");
  EXPECT_EQ(files().size(), 1u);
}

TEST_F(AtomicFileTest, MissingDirectoryIsAClearError) {
  try {
    ncinterp::AtomicOutputFile f(path("no/such/dir/out.txt"));
    FAIL() << "expected an error";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("no/such/dir/out.txt"), std::string::npos) << e.what();
  }
}

TEST_F(AtomicFileTest, TwoWritersGetDistinctTemporaries) {
  ncinterp::AtomicOutputFile a(path("x.csv"));
  ncinterp::AtomicOutputFile b(path("x.csv"));
  EXPECT_NE(a.temp_path(), b.temp_path());
}

TEST_F(AtomicFileTest, BytesHelperWritesBinary) {
  const std::vector<uint8_t> bytes = {0x00, 0xA5, 0x0A, 0xFF};
  ncinterp::write_file_atomically(path("b.tape"), bytes);
  const std::string got = slurp(path("b.tape"));
  ASSERT_EQ(got.size(), 4u);
  EXPECT_EQ(static_cast<uint8_t>(got[1]), 0xA5);
  EXPECT_EQ(static_cast<uint8_t>(got[3]), 0xFF);
}

}  // namespace
