// Synthesis result cache (see synth_cache.h).
#include "synth_cache.h"

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>

#include "atomic_file.h"
#include "subprocess.h"

namespace ncinterp::sweep {
namespace {

constexpr uint64_t kFnvOffset = 1469598103934665603ull;
constexpr uint64_t kFnvPrime = 1099511628211ull;

void fnv(uint64_t& h, const std::string& bytes) {
  for (unsigned char c : bytes) {
    h ^= c;
    h *= kFnvPrime;
  }
  // A separator, so that ("ab", "c") and ("a", "bc") differ.
  h ^= 0xff;
  h *= kFnvPrime;
}

nlohmann::json to_json(const Measured& m) {
  if (m.value) return *m.value;
  return {{"reason", m.reason}};
}

Measured from_json(const nlohmann::json& j) {
  if (j.is_number()) return Measured::of(j.get<double>());
  return Measured::absent(j.at("reason").get<std::string>());
}

}  // namespace

std::string content_hash(const std::vector<std::string>& files, const std::vector<std::string>& extra) {
  uint64_t h = kFnvOffset;
  for (const std::string& f : files) {
    fnv(h, std::filesystem::path(f).filename().string());
    fnv(h, read_text_file(f));
  }
  for (const std::string& e : extra) fnv(h, e);
  char hex[17];
  std::snprintf(hex, sizeof hex, "%016llx", static_cast<unsigned long long>(h));
  return hex;
}

std::string SynthCache::path(const std::string& tag) const { return dir_ + "/" + key_ + "-" + tag + ".json"; }

nlohmann::json measured_json(const Measured& m) { return to_json(m); }
Measured measured_from_json(const nlohmann::json& j) { return from_json(j); }

nlohmann::json synth_result_json(const SynthResult& r) {
  return {{"cells", to_json(r.cells)},
          {"flip_flops", to_json(r.flip_flops)},
          {"ice40_luts", to_json(r.ice40_luts)},
          {"ice40_logic_cells", to_json(r.ice40_logic_cells)},
          {"fmax_mhz", to_json(r.fmax_mhz)},
          {"small_logic_cells", to_json(r.small_logic_cells)},
          {"small_fmax_mhz", to_json(r.small_fmax_mhz)}};
}

SynthResult synth_result_from_json(const nlohmann::json& j) {
  SynthResult r;
  r.cells = from_json(j.at("cells"));
  r.flip_flops = from_json(j.at("flip_flops"));
  r.ice40_luts = from_json(j.at("ice40_luts"));
  r.ice40_logic_cells = from_json(j.at("ice40_logic_cells"));
  r.fmax_mhz = from_json(j.at("fmax_mhz"));
  r.small_logic_cells = from_json(j.at("small_logic_cells"));
  r.small_fmax_mhz = from_json(j.at("small_fmax_mhz"));
  return r;
}

std::optional<SynthResult> SynthCache::load(const std::string& tag) const {
  if (dir_.empty()) return std::nullopt;
  std::ifstream in(path(tag));
  if (!in) return std::nullopt;
  try {
    SynthResult r = synth_result_from_json(nlohmann::json::parse(in));
    r.from_cache = true;
    return r;
  } catch (const std::exception&) {
    return std::nullopt;  // unreadable or from another version: synthesise again
  }
}

void SynthCache::store(const std::string& tag, const SynthResult& r) const {
  if (dir_.empty()) return;
  nlohmann::json j = synth_result_json(r);
  j["parameters"] = tag;
  try {
    std::filesystem::create_directories(dir_);
    write_file_atomically(path(tag), j.dump(2) + "\n");
  } catch (const std::exception&) {
    // A cache that cannot be written only costs time on the next run.
  }
}

}  // namespace ncinterp::sweep
