// The outputs of one command run, all or nothing.
// Idea: a command names its inputs and reserves every output before it starts the work, so
// a bad output path (a missing or read-only directory, a directory, an output that is one
// of the inputs, the same output twice) fails in a second instead of after the whole run.
// Each output is an AtomicOutputFile (its temporary exists from the start); commit() renames
// them all at the end, and if one fails, the ones already renamed are removed again. An
// OutputSet destroyed without commit() (an error, an exception) leaves no output at all.
#pragma once
#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include "atomic_file.h"

namespace ncinterp {

class OutputSet {
 public:
  // A file the run reads: no output may be the same file (same device and inode, through
  // any symlink). Call before add(). A missing input is not an error here (its reader says).
  void input(const std::string& path);

  // Reserves an output; nullptr for an empty path (an option not given). Throws
  // std::runtime_error naming the path when it cannot be written or is an input.
  AtomicOutputFile* add(const std::string& path);

  // Writes the whole content of an output reserved by add() (nothing for nullptr).
  static void write(AtomicOutputFile* file, std::string_view content);

  // The file is not to be written after all (its temporary is removed).
  void discard(AtomicOutputFile* file);

  // Commits every output not discarded; on a failure removes the ones already committed
  // (stream targets cannot be taken back) and rethrows.
  void commit();

 private:
  struct FileId {
    unsigned long long dev, ino;
  };
  std::vector<std::pair<std::string, FileId>> inputs_;
  std::vector<std::unique_ptr<AtomicOutputFile>> outputs_;
};

}  // namespace ncinterp
