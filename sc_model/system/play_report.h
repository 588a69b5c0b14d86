// The JSON report of a play run (design.md section 4: blocks, cycles, pulses, final
// position, max path error, status, error) plus what a user needs to judge the run:
// engine, clock, reader rate, gaps, feed accuracy, path bound, expected position.
#pragma once
#include <optional>
#include <string>

#include <nlohmann/json.hpp>

#include "play_run.h"
#include "tape.h"

namespace ncinterp::system {

struct PlayErrorText {
  uint32_t block = 0;
  uint64_t offset = 0;
  std::string message;
};

// The error a run stopped on, in words: the engine's code, block and offset, with the
// software reader's more detailed message when it found the same error (it should: both
// apply the same rules), else the generic message of the code. nullopt when the run is ok.
std::optional<PlayErrorText> play_error(const PlayResult& r,
                                        const std::optional<tape::TapeErrorInfo>& reader_error);

nlohmann::json play_report(const PlayResult& r, const std::string& tape_path,
                           const std::string& engine_name,
                           const std::optional<tape::TapeErrorInfo>& reader_error);

}  // namespace ncinterp::system
