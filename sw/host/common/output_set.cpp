// The outputs of one run (see output_set.h): reserved up front, committed together.
#include "output_set.h"

#include <sys/stat.h>

#include <algorithm>
#include <cstdio>
#include <stdexcept>

namespace ncinterp {

void OutputSet::input(const std::string& path) {
  struct stat st {};
  if (path.empty() || path == "-" || ::stat(path.c_str(), &st) != 0) return;
  inputs_.push_back({path, {static_cast<unsigned long long>(st.st_dev),
                            static_cast<unsigned long long>(st.st_ino)}});
}

AtomicOutputFile* OutputSet::add(const std::string& path) {
  if (path.empty()) return nullptr;
  const std::string target = path == "-" ? path : resolve_output_path(path);
  struct stat st {};
  if (path != "-" && ::stat(target.c_str(), &st) == 0 && S_ISREG(st.st_mode)) {
    for (const auto& [name, id] : inputs_)
      if (id.dev == static_cast<unsigned long long>(st.st_dev) &&
          id.ino == static_cast<unsigned long long>(st.st_ino))
        throw std::runtime_error(path + ": is the input " + name + "; refusing to overwrite it");
  }
  for (const auto& out : outputs_)
    if (out->target_path() == target || (path == "-" && out->path() == "-"))
      throw std::runtime_error(path + ": named twice as an output");
  outputs_.push_back(std::make_unique<AtomicOutputFile>(path));
  return outputs_.back().get();
}

void OutputSet::write(AtomicOutputFile* file, std::string_view content) {
  if (file) file->stream().write(content.data(), static_cast<std::streamsize>(content.size()));
}

void OutputSet::discard(AtomicOutputFile* file) {
  outputs_.erase(std::remove_if(outputs_.begin(), outputs_.end(),
                                [file](const auto& out) { return out.get() == file; }),
                 outputs_.end());
}

void OutputSet::commit() {
  for (size_t i = 0; i < outputs_.size(); ++i) {
    try {
      outputs_[i]->commit();
    } catch (...) {
      for (size_t k = 0; k < i; ++k)
        if (!outputs_[k]->streamed()) std::remove(outputs_[k]->target_path().c_str());
      throw;
    }
  }
}

}  // namespace ncinterp
