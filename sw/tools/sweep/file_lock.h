// An exclusive advisory lock on a file (flock), held for the object's lifetime.
// Idea: sweep points that share one synthesis (they differ only in clock_hz or the
// inputs) may run at the same time, as threads (--jobs) or as processes (GNU parallel,
// Slurm on one node); the lock makes the second wait for the first and then find its
// result in the cache, instead of synthesising the same netlist again into the same work
// directory. flock locks belong to an open file, so two threads of one process exclude
// each other too. A lock that cannot be taken (e.g. a read-only directory) is not an
// error: the work then runs unlocked, as it would without this class.
#pragma once
#include <string>

namespace ncinterp::sweep {

class FileLock {
 public:
  explicit FileLock(const std::string& path);  // blocks until the lock is held
  ~FileLock();
  FileLock(const FileLock&) = delete;
  FileLock& operator=(const FileLock&) = delete;
  bool held() const { return fd_ >= 0; }

 private:
  int fd_ = -1;
};

}  // namespace ncinterp::sweep
