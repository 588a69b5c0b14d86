// Progress of a long run on a terminal: one line on stderr, rewritten in place at most five
// times a second, erased at the end; nothing at all when stderr is not a terminal (a pipe,
// a file, a test), so the commands' output stays the same there.
// Idea: one small helper for every command (check, cosim, play, sweep, methods) instead of
// a copy in each: the command says what to show, the helper decides when and whether.
#pragma once
#include <chrono>
#include <string>

namespace ncinterp {

class Progress {
 public:
  // `name` starts the line ("check: ..."). Enabled when stderr is a terminal.
  explicit Progress(std::string name);
  ~Progress();
  Progress(const Progress&) = delete;
  Progress& operator=(const Progress&) = delete;

  bool enabled() const { return enabled_; }
  // True when a call to show() would be drawn now (enabled and 200 ms since the last one):
  // lets a caller skip building the text.
  bool due() const;
  // Shows "name: text" (throttled; `force` draws anyway, e.g. for a stage change).
  void show(const std::string& text, bool force = false);
  // Erases the line (also done by the destructor).
  void clear();

 private:
  std::string name_;
  bool enabled_;
  bool shown_ = false;
  std::chrono::steady_clock::time_point last_{};
};

}  // namespace ncinterp
