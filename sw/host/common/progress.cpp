// Progress line on a terminal (see progress.h).
#include "progress.h"

#include <unistd.h>

#include <cstdio>

namespace ncinterp {

Progress::Progress(std::string name) : name_(std::move(name)), enabled_(isatty(STDERR_FILENO) != 0) {}

Progress::~Progress() { clear(); }

bool Progress::due() const {
  return enabled_ && std::chrono::steady_clock::now() - last_ >= std::chrono::milliseconds(200);
}

void Progress::show(const std::string& text, bool force) {
  if (!enabled_ || !(force || due())) return;
  last_ = std::chrono::steady_clock::now();
  // \r and "erase to end of line": a shorter line leaves nothing of the longer one.
  std::fprintf(stderr, "\r\033[K%s: %s", name_.c_str(), text.c_str());
  std::fflush(stderr);
  shown_ = true;
}

void Progress::clear() {
  if (!shown_) return;
  std::fprintf(stderr, "\r\033[K");
  std::fflush(stderr);
  shown_ = false;
}

}  // namespace ncinterp
