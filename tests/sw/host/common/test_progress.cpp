// Progress: silent when stderr is not a terminal (pipes, files, these tests under ctest);
// on a terminal (a pseudo-terminal here) one line, rewritten in place and erased.
#include <gtest/gtest.h>
#include <pty.h>
#include <unistd.h>

#include <string>

#include "progress.h"

namespace {

// Runs f with stderr on a fresh pseudo-terminal; returns what it wrote there.
template <class F>
std::string on_terminal(F f) {
  int master = -1, slave = -1;
  if (openpty(&master, &slave, nullptr, nullptr, nullptr) != 0) return "openpty failed";
  const int saved = dup(STDERR_FILENO);
  dup2(slave, STDERR_FILENO);
  f();
  dup2(saved, STDERR_FILENO);
  close(saved);
  close(slave);
  std::string out;
  char buf[256];
  ssize_t n;
  while ((n = read(master, buf, sizeof buf)) > 0) {
    out.append(buf, static_cast<size_t>(n));
    if (out.find("\r\033[K", out.size() >= 3 ? out.size() - 3 : 0) != std::string::npos) break;
  }
  close(master);
  return out;
}

TEST(Progress, SilentWithoutATerminal) {
  if (isatty(STDERR_FILENO)) GTEST_SKIP() << "stderr is a terminal here";
  testing::internal::CaptureStderr();
  {
    ncinterp::Progress p("check");
    EXPECT_FALSE(p.enabled());
    p.show("1 clocks", true);
  }
  EXPECT_EQ(testing::internal::GetCapturedStderr(), "");
}

TEST(Progress, OneLineOnATerminalErasedAtTheEnd) {
  const std::string out = on_terminal([] {
    ncinterp::Progress p("play");
    EXPECT_TRUE(p.enabled());
    p.show("cycle 5", true);
    p.show("cycle 6");  // within 200 ms of the last: not drawn
  });
  EXPECT_EQ(out, "\r\033[Kplay: cycle 5\r\033[K");
}

}  // namespace
