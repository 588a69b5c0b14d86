// Atomic output files (see atomic_file.h): exclusive temporary beside the target, rename on
// commit, unlink otherwise.
#include "atomic_file.h"

#include <fcntl.h>
#include <unistd.h>

#include <atomic>
#include <cerrno>
#include <chrono>
#include <cstdio>
#include <cstring>
#include <stdexcept>

namespace ncinterp {

namespace {

std::runtime_error file_error(const std::string& path, const std::string& what, int err) {
  return std::runtime_error(path + ": " + what + ": " + std::strerror(err));
}

// "dir/" and "name.ext" of a path; the extension is everything from the last '.' of the
// name (none for dot files without a further dot).
void split_path(const std::string& path, std::string& dir, std::string& name,
                std::string& ext) {
  const auto slash = path.rfind('/');
  dir = slash == std::string::npos ? std::string() : path.substr(0, slash + 1);
  name = slash == std::string::npos ? path : path.substr(slash + 1);
  const auto dot = name.rfind('.');
  ext = dot == std::string::npos || dot == 0 ? std::string() : name.substr(dot);
}

}  // namespace

AtomicOutputFile::AtomicOutputFile(std::string path) : path_(std::move(path)) {
  if (path_.empty() || path_.back() == '/')
    throw std::runtime_error(path_ + ": not a file name");
  std::string dir, name, ext;
  split_path(path_, dir, name, ext);
  // A unique name from the pid, a process-wide counter and the clock; O_EXCL makes a
  // collision with any other file an error we retry instead of an overwrite.
  static std::atomic<unsigned> counter{0};
  for (int attempt = 0; attempt < 100; ++attempt) {
    const auto stamp = static_cast<unsigned long long>(
        std::chrono::steady_clock::now().time_since_epoch().count());
    char tag[64];
    std::snprintf(tag, sizeof tag, "%x%x%llx", static_cast<unsigned>(getpid()),
                  counter.fetch_add(1), stamp & 0xffffff);
    std::string candidate = dir + "." + name + "." + tag + ext;
    const int fd = ::open(candidate.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0666);
    if (fd >= 0) {
      ::close(fd);
      temp_path_ = std::move(candidate);
      return;
    }
    if (errno != EEXIST) throw file_error(path_, "cannot create a temporary file", errno);
  }
  throw std::runtime_error(path_ + ": cannot create a unique temporary file");
}

AtomicOutputFile::~AtomicOutputFile() {
  if (committed_) return;
  if (stream_.is_open()) stream_.close();
  std::remove(temp_path_.c_str());
}

std::ostream& AtomicOutputFile::stream() {
  if (!stream_.is_open() && !committed_) {
    stream_.open(temp_path_, std::ios::binary | std::ios::trunc);
    if (!stream_) throw file_error(path_, "cannot open for writing", errno);
  }
  return stream_;
}

void AtomicOutputFile::commit() {
  if (committed_) return;
  if (stream_.is_open()) {
    stream_.flush();
    const bool ok = static_cast<bool>(stream_);
    stream_.close();
    if (!ok || stream_.fail()) throw std::runtime_error(path_ + ": write failed");
  }
  if (std::rename(temp_path_.c_str(), path_.c_str()) != 0)
    throw file_error(path_, "cannot rename the finished file into place", errno);
  committed_ = true;
}

void write_file_atomically(const std::string& path, std::string_view content) {
  AtomicOutputFile file(path);
  file.stream().write(content.data(), static_cast<std::streamsize>(content.size()));
  file.commit();
}

void write_file_atomically(const std::string& path, const std::vector<uint8_t>& bytes) {
  write_file_atomically(
      path, std::string_view(reinterpret_cast<const char*>(bytes.data()), bytes.size()));
}

}  // namespace ncinterp
