// Cache of synthesis results per (RTL source hash, W) in the build directory, so that a
// rerun of the sweep does not synthesise and place again what has not changed.
// Idea: the key is a hash of everything the result depends on (the content of every RTL
// file and of the place-and-route harness, the tool commands, the tools' versions) plus W;
// a result is stored only when every tool ran to completion (a missing tool or a killed
// run is not a property of the design). Files are written atomically.
#pragma once
#include <optional>
#include <string>
#include <vector>

#include "sweep_row.h"

namespace ncinterp::sweep {

// 16 hex digits (64-bit FNV-1a) over the files' contents and the extra strings. A file
// that cannot be read hashes as its name alone (the synthesis then fails and says why).
std::string content_hash(const std::vector<std::string>& files, const std::vector<std::string>& extra);

class SynthCache {
 public:
  // dir empty: no cache (load finds nothing, store does nothing).
  SynthCache(std::string dir, std::string key) : dir_(std::move(dir)), key_(std::move(key)) {}
  std::optional<SynthResult> load(unsigned width) const;
  void store(unsigned width, const SynthResult& result) const;  // best effort
  std::string path(unsigned width) const;

 private:
  std::string dir_, key_;
};

}  // namespace ncinterp::sweep
