// AtomicOutputFile: the target appears only on commit, complete; nothing is left behind
// when the writer gives up; an existing target survives a failed rewrite; a symlink is
// written through (it stays a link), a FIFO or a device is streamed, never replaced.
#include <gtest/gtest.h>

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

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

TEST_F(AtomicFileTest, SymlinkIsWrittenThroughAndStaysALink) {
  write("target.tape", "old");
  fs::create_symlink("target.tape", path("link.tape"));
  ncinterp::write_file_atomically(path("link.tape"), std::string_view("new"));
  EXPECT_TRUE(fs::is_symlink(path("link.tape")));
  EXPECT_EQ(slurp(path("target.tape")), "new");
  EXPECT_EQ(files(), (std::vector<std::string>{"link.tape", "target.tape"}));
}

TEST_F(AtomicFileTest, DanglingSymlinkCreatesItsTarget) {
  fs::create_directory(path("sub"));
  fs::create_symlink("sub/made.json", path("link.json"));
  ncinterp::write_file_atomically(path("link.json"), std::string_view("{}"));
  EXPECT_TRUE(fs::is_symlink(path("link.json")));
  EXPECT_EQ(slurp(path("sub/made.json")), "{}");
}

TEST_F(AtomicFileTest, SymlinkLoopIsAClearError) {
  fs::create_symlink("b", path("a"));
  fs::create_symlink("a", path("b"));
  EXPECT_THROW(ncinterp::AtomicOutputFile f(path("a")), std::runtime_error);
}

TEST_F(AtomicFileTest, CharacterDeviceIsStreamedNotReplaced) {
  ncinterp::AtomicOutputFile f("/dev/null");
  EXPECT_TRUE(f.streamed());
  f.stream() << "discarded";
  f.commit();
  struct stat st {};
  ASSERT_EQ(::stat("/dev/null", &st), 0);
  EXPECT_TRUE(S_ISCHR(st.st_mode));
}

TEST_F(AtomicFileTest, FifoIsStreamedNotReplaced) {
  ASSERT_EQ(::mkfifo(path("pipe").c_str(), 0600), 0);
  // The reader opens non-blocking first, so the writer's open does not wait.
  const int rfd = ::open(path("pipe").c_str(), O_RDONLY | O_NONBLOCK);
  ASSERT_GE(rfd, 0);
  {
    ncinterp::AtomicOutputFile f(path("pipe"));
    EXPECT_TRUE(f.streamed());
    f.stream() << "through";
    f.commit();
  }
  char buf[16] = {};
  EXPECT_EQ(::read(rfd, buf, sizeof buf), 7);
  ::close(rfd);
  EXPECT_EQ(std::string(buf), "through");
  struct stat st {};
  ASSERT_EQ(::stat(path("pipe").c_str(), &st), 0);
  EXPECT_TRUE(S_ISFIFO(st.st_mode));
  EXPECT_EQ(files(), std::vector<std::string>{"pipe"});
}

TEST_F(AtomicFileTest, DashIsStandardOutput) {
  ncinterp::AtomicOutputFile f("-");
  EXPECT_TRUE(f.streamed());
  EXPECT_EQ(f.target_path(), "/dev/stdout");
}

TEST_F(AtomicFileTest, DirectoryIsRefused) {
  fs::create_directory(path("d"));
  EXPECT_THROW(ncinterp::AtomicOutputFile f(path("d")), std::runtime_error);
  EXPECT_EQ(files(), std::vector<std::string>{"d"});
}

}  // namespace
