// Atomic output files: no half-written output, ever, and nothing replaced that should be
// written through.
// Idea: a regular file is written to a temporary file in the same directory as the target
// (so rename() stays on one file system and is atomic), then renamed over the target on
// commit(). If the object is destroyed without commit() (an exception, an error exit), the
// temporary is removed and the target is untouched. A symlink is followed first: the
// temporary goes beside the file the link points to and replaces that file, so the link
// stays a link. A FIFO, a character device (/dev/null, a terminal, /dev/stdout) or "-"
// (standard output) cannot be replaced and is not meant to be: it is written directly
// ("streamed"), and commit() only flushes. Tools that open files by name themselves
// (Verilator's and SystemC's VCD tracers) write to temp_path() and the caller commits when
// they are done.
#pragma once
#include <cstdint>
#include <fstream>
#include <string>
#include <string_view>
#include <vector>

namespace ncinterp {

class AtomicOutputFile {
 public:
  // Reserves a fresh temporary name beside the target (created empty, exclusive), or, for a
  // stream target, checks that it can be opened. The temporary keeps the target's extension
  // ("dir/.out.vcd.ab12cd.vcd" for "dir/out.vcd") because some tools append or check it.
  // Throws std::runtime_error naming `path` if it cannot (a directory, a missing or
  // read-only directory, a symlink loop).
  explicit AtomicOutputFile(std::string path);
  ~AtomicOutputFile();
  AtomicOutputFile(const AtomicOutputFile&) = delete;
  AtomicOutputFile& operator=(const AtomicOutputFile&) = delete;

  // Stream on the temporary file, or on the stream target (opened on first use, binary).
  std::ostream& stream();
  // The path as given (messages name it).
  const std::string& path() const { return path_; }
  // What is finally written: the target with every symlink followed ("/dev/stdout" for "-").
  const std::string& target_path() const { return target_; }
  // Where the content goes before commit: the temporary, or the target itself when streamed.
  const std::string& temp_path() const { return temp_path_; }
  // True for a FIFO, a character device or "-": written directly, never renamed or removed.
  bool streamed() const { return streamed_; }
  bool committed() const { return committed_; }

  // Flushes and closes the stream (if used) and renames the temporary over the target.
  // Throws std::runtime_error naming the target on any write or rename failure (the
  // temporary is then removed by the destructor).
  void commit();

 private:
  std::string path_;
  std::string target_;
  std::string temp_path_;
  std::ofstream stream_;
  bool streamed_ = false;
  bool committed_ = false;
};

// The target a path names with every symlink followed (also a dangling one: the file the
// link would create). Throws std::runtime_error on a symlink loop.
std::string resolve_output_path(const std::string& path);

// One-shot helpers: the whole content at once, written atomically.
void write_file_atomically(const std::string& path, std::string_view content);
void write_file_atomically(const std::string& path, const std::vector<uint8_t>& bytes);

}  // namespace ncinterp
