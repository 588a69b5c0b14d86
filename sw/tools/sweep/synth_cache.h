// Cache of synthesis results per (RTL source hash, RTL parameters) in the build directory, so that a
// rerun of the sweep does not synthesise and place again what has not changed.
// Idea: the key is a hash of everything the result depends on (the content of every RTL
// file and of the place-and-route harness, the tool commands, the tools' versions) plus the
// parameter set (W, FeedWidth, ...);
// a result is stored only when every tool ran to completion (a missing tool or a killed
// run is not a property of the design). Files are written atomically.
#pragma once
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "sweep_row.h"

namespace ncinterp::sweep {

// 16 hex digits (64-bit FNV-1a) over the files' contents and the extra strings. A file
// that cannot be read hashes as its name alone (the synthesis then fails and says why).
std::string content_hash(const std::vector<std::string>& files, const std::vector<std::string>& extra);

// A measured value or its reason as JSON (a number, or {"reason": ...}), and back; the
// same for a whole synthesis result (also used by the point results, point_store.h).
nlohmann::json measured_json(const Measured& m);
Measured measured_from_json(const nlohmann::json& j);
nlohmann::json synth_result_json(const SynthResult& r);
SynthResult synth_result_from_json(const nlohmann::json& j);  // throws on a malformed object

class SynthCache {
 public:
  // dir empty: no cache (load finds nothing, store does nothing).
  SynthCache(std::string dir, std::string key) : dir_(std::move(dir)), key_(std::move(key)) {}
  // tag: the parameter set (parameter_tag in synthesis.h); a width W alone is "w<W>".
  std::optional<SynthResult> load(const std::string& tag) const;
  void store(const std::string& tag, const SynthResult& result) const;  // best effort
  std::string path(const std::string& tag) const;
  std::optional<SynthResult> load(unsigned width) const { return load(width_tag(width)); }
  void store(unsigned width, const SynthResult& r) const { store(width_tag(width), r); }
  std::string path(unsigned width) const { return path(width_tag(width)); }
  static std::string width_tag(unsigned width) { return "w" + std::to_string(width); }

 private:
  std::string dir_, key_;
};

}  // namespace ncinterp::sweep
