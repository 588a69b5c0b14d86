// Atomic output files (see atomic_file.h): symlinks followed, streams written directly,
// regular files through an exclusive temporary beside the target, renamed on commit,
// unlinked otherwise.
#include "atomic_file.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <atomic>
#include <cerrno>
#include <chrono>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <stdexcept>

namespace ncinterp {

namespace {

namespace fs = std::filesystem;

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

bool is_kernel_path(const std::string& p) {
  return p.rfind("/dev/", 0) == 0 || p.rfind("/proc/", 0) == 0;
}

}  // namespace

std::string resolve_output_path(const std::string& path) {
  fs::path p(path);
  for (int hop = 0; hop < 40; ++hop) {
    std::error_code ec;
    // /dev/stdout -> /proc/self/fd/1 -> "pipe:[123]": the kernel's links are not files to
    // replace; stat() follows them to the real object.
    if (is_kernel_path(p.string()) || !fs::is_symlink(p, ec)) return p.string();
    const fs::path to = fs::read_symlink(p, ec);
    if (ec) throw file_error(path, "cannot read the symbolic link", ec.value());
    p = to.is_absolute() ? to : p.parent_path() / to;
  }
  throw std::runtime_error(path + ": too many levels of symbolic links");
}

AtomicOutputFile::AtomicOutputFile(std::string path) : path_(std::move(path)) {
  if (path_.empty() || path_.back() == '/')
    throw std::runtime_error(path_ + ": not a file name");
  target_ = path_ == "-" ? std::string("/dev/stdout") : resolve_output_path(path_);
  struct stat st {};
  const bool exists = ::stat(target_.c_str(), &st) == 0;
  if (exists && S_ISDIR(st.st_mode)) throw std::runtime_error(path_ + ": is a directory");
  if (path_ == "-" || is_kernel_path(target_) || (exists && !S_ISREG(st.st_mode))) {
    // Standard output, a FIFO, a device or a socket: written in place. access() instead
    // of open() because opening a FIFO for writing waits for its reader.
    if (::access(target_.c_str(), W_OK) != 0) throw file_error(path_, "cannot write", errno);
    streamed_ = true;
    temp_path_ = target_;
    return;
  }
  std::string dir, name, ext;
  split_path(target_, dir, name, ext);
  struct stat dst {};
  if (::stat(dir.empty() ? "." : dir.c_str(), &dst) != 0 || !S_ISDIR(dst.st_mode))
    throw std::runtime_error(path_ + ": directory " + (dir.empty() ? "." : dir) + " does not exist");
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
    if (errno != EEXIST) throw file_error(path_, "cannot create a file in its directory", errno);
  }
  throw std::runtime_error(path_ + ": cannot create a unique temporary file");
}

AtomicOutputFile::~AtomicOutputFile() {
  if (stream_.is_open()) stream_.close();
  if (committed_ || streamed_) return;  // a stream target is never removed
  std::remove(temp_path_.c_str());
}

std::ostream& AtomicOutputFile::stream() {
  if (!stream_.is_open() && !committed_) {
    // A stream target is not truncated (O_TRUNC means nothing to a FIFO or a device, and
    // "-" may be a file the shell opened for appending).
    stream_.open(temp_path_, streamed_ ? std::ios::binary | std::ios::out | std::ios::app
                                       : std::ios::binary | std::ios::trunc);
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
  if (!streamed_ && std::rename(temp_path_.c_str(), target_.c_str()) != 0)
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
