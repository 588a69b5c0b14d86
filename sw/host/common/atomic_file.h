// Atomic output files: no half-written output, ever.
// Idea: write to a temporary file in the same directory as the target (so rename() stays
// on one file system and is atomic), then rename it over the target on commit(). If the
// object is destroyed without commit() (an exception, an error exit), the temporary is
// removed and the target is untouched. Tools that open files by name themselves (Verilator's
// and SystemC's VCD tracers) write to temp_path() and the caller commits when they are done.
#pragma once
#include <cstdint>
#include <fstream>
#include <string>
#include <string_view>
#include <vector>

namespace ncinterp {

class AtomicOutputFile {
 public:
  // Reserves a fresh temporary name beside `path` (created empty, exclusive). The temporary
  // keeps the target's extension ("dir/.out.vcd.ab12cd.vcd" for "dir/out.vcd") because some
  // tools append or check it. Throws std::runtime_error naming `path` if it cannot.
  explicit AtomicOutputFile(std::string path);
  ~AtomicOutputFile();
  AtomicOutputFile(const AtomicOutputFile&) = delete;
  AtomicOutputFile& operator=(const AtomicOutputFile&) = delete;

  // Stream on the temporary file (opened on first use, binary).
  std::ostream& stream();
  const std::string& path() const { return path_; }
  const std::string& temp_path() const { return temp_path_; }
  bool committed() const { return committed_; }

  // Flushes and closes the stream (if used) and renames the temporary over the target.
  // Throws std::runtime_error naming the target on any write or rename failure (the
  // temporary is then removed by the destructor).
  void commit();

 private:
  std::string path_;
  std::string temp_path_;
  std::ofstream stream_;
  bool committed_ = false;
};

// One-shot helpers: the whole content at once, written atomically.
void write_file_atomically(const std::string& path, std::string_view content);
void write_file_atomically(const std::string& path, const std::vector<uint8_t>& bytes);

}  // namespace ncinterp
