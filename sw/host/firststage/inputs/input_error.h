// Bad input: one line "FILE:LINE: what is wrong" (line 0 = the file as a whole).
#pragma once
#include <stdexcept>
#include <string>

namespace ncinterp::firststage {

class InputError : public std::runtime_error {
 public:
  InputError(const std::string& file, int line, const std::string& what)
      : std::runtime_error(file + ":" + std::to_string(line) + ": " + what),
        file_(file), line_(line) {}
  const std::string& file() const { return file_; }
  int line() const { return line_; }

 private:
  std::string file_;
  int line_;
};

}  // namespace ncinterp::firststage
