// JSON report of a play run (see play_report.h).
#include "play_report.h"

#include <algorithm>

namespace ncinterp::system {

std::optional<PlayErrorText> play_error(const PlayResult& r,
                                        const std::optional<tape::TapeErrorInfo>& reader) {
  const PlaySummary& s = r.summary;
  if (s.error) {
    PlayErrorText e{s.error_block, s.error_offset, ""};
    const bool same = reader && reader->code == s.error_code && reader->block == s.error_block &&
                      reader->offset == s.error_offset;
    e.message = same ? reader->message
                     : tape_error_message(static_cast<TapeError>(s.error_code)) +
                           std::string(" (error code ") + std::to_string(s.error_code) + ")";
    return e;
  }
  if (r.limit_reached)
    return PlayErrorText{s.timeline.empty() ? 0 : s.timeline.back().n, r.frames_taken,
                         "stopped at the cycle limit (" + std::to_string(r.max_cycles) +
                             " cycles) before the end of the program; block = the last "
                             "block loaded, offset = frames read"};
  return std::nullopt;
}

nlohmann::json play_report(const PlayResult& r, const std::string& tape_path,
                           const std::string& engine_name,
                           const std::optional<tape::TapeErrorInfo>& reader_error) {
  const PlaySummary& s = r.summary;
  nlohmann::json j;
  j["tape"] = tape_path;
  j["engine"] = engine_name;
  j["arch"] = arch_name(r.config.arch);
  j["accel_mm_s2"] = r.accel_mm_s2;
  j["status"] = r.ok() ? "ok" : r.stopped() ? "stopped" : s.paused ? "paused" : "error";
  j["blocks"] = s.blocks_played;
  j["blocks_on_tape"] = r.blocks_on_tape;
  j["cycles"] = s.cycles;
  j["simulated_seconds"] = static_cast<double>(s.cycles) / r.clock_hz;
  j["pulses"] = {{"x", {{"plus", s.pulses_x.plus}, {"minus", s.pulses_x.minus}}},
                 {"y", {{"plus", s.pulses_y.plus}, {"minus", s.pulses_y.minus}}}};
  j["final_position_blu"] = {{"x", s.final_x}, {"y", s.final_y}};
  j["expected_position_blu"] = {{"x", s.expected_x}, {"y", s.expected_y}};
  j["max_path_error_blu"] = s.max_path_error;
  j["max_path_error_block"] = s.max_path_error_block;
  j["path_within_bound"] = s.path_within_bound;
  j["pulses_beyond_program"] = s.pulses_beyond_program;
  j["clock_hz"] = r.clock_hz;
  j["reader_cps"] = r.reader_cps;
  j["cycles_per_frame"] = r.cycles_per_frame;
  j["frames"] = r.frames;
  j["frames_read"] = r.frames_taken;
  j["lead_in_cycles"] = s.lead_in_cycles;
  j["gap_cycles"] = s.gap_cycles;
  j["busy_cycles"] = s.busy_cycles;
  j["paused_cycles"] = s.paused_cycles;
  j["tool_on_cycles"] = s.tool_on_cycles;
  j["feed"] = {{"timed_blocks", s.timed_blocks},
               {"saturated_blocks", s.saturated_blocks},
               {"worst_relative_time_error", s.worst_relative_time_error},
               {"worst_time_error_cycles", s.worst_time_error_cycles},
               {"worst_block", s.worst_time_error_block}};
  if (!r.vcd_path.empty())  // edges from_cycle..to_cycle; no file when the run failed
    j["vcd"] = {{"file", r.vcd_written ? nlohmann::json(r.vcd_path) : nlohmann::json()},
                {"from_cycle", r.vcd_window.from},
                {"to_cycle", std::min(r.vcd_window.to, s.cycles)}};
  j["cycle_limit"] = r.max_cycles;
  j["wall_seconds"] = r.wall_seconds;
  // The software reader (sw/host/tape) and the engine's decoder apply the same rules: they must
  // agree on whether and where the tape is bad. A stop ends the run before the engine may
  // have read that far.
  const bool agree = r.stopped() ? true
                     : reader_error ? s.error && reader_error->code == s.error_code &&
                                          reader_error->block == s.error_block &&
                                          reader_error->offset == s.error_offset
                                    : !s.error;
  j["reader_agrees"] = agree;
  if (const auto e = play_error(r, reader_error))
    j["error"] = {{"block", e->block}, {"offset", e->offset}, {"message", e->message}};
  if (s.error && j.contains("error")) j["error"]["code"] = s.error_code;
  return j;
}

}  // namespace ncinterp::system
