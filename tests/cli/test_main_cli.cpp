// The ncinterp executable as a whole: --version, --help, and the exit-code rule for usage
// errors that no command sees (no command, an unknown command): exit 1 with one line.
#include <gtest/gtest.h>

#include <algorithm>

#include "cli_test.h"

namespace ncinterp::test {
namespace {

using MainCli = CliTest;

TEST_F(MainCli, VersionNamesTheProgramAndExitsZero) {
  ASSERT_EQ(run("--version"), 0) << stderr_;
  EXPECT_EQ(stdout_.rfind("ncinterp 0.", 0), 0u) << stdout_;
}

TEST_F(MainCli, HelpExitsZero) {
  ASSERT_EQ(run("--help"), 0) << stderr_;
  EXPECT_NE(stdout_.find("tape"), std::string::npos) << stdout_;
  ASSERT_EQ(run("tape --help"), 0) << stderr_;
}

TEST_F(MainCli, NoCommandOrUnknownCommandExitsOneWithOneLine) {
  EXPECT_EQ(run(""), 1);
  EXPECT_EQ(std::count(stderr_.begin(), stderr_.end(), '\n'), 1) << stderr_;
  EXPECT_EQ(run("punch"), 1);
  EXPECT_EQ(std::count(stderr_.begin(), stderr_.end(), '\n'), 1) << stderr_;
  EXPECT_EQ(stderr_.rfind("ncinterp: ", 0), 0u) << stderr_;
}

}  // namespace
}  // namespace ncinterp::test
