// A board's bitstream: yosys (synth_ice40) -> nextpnr-ice40 with the board's .pcf ->
// icepack, and the verdict: logic cells used of the part's, Fmax against the board clock.
// Idea: the tools run as child processes through the sweep's helpers (sw/tools/sweep/
// subprocess.h, synth_logs.h: the same runner and log parsers as the bit-width sweep), their
// logs kept in a work directory. The result says plainly why there is no bitstream: the
// design does not fit (cells needed vs available), misses the board clock, or a tool
// failed (its first error line). At high utilisation the Fmax depends on the placement
// seed by a few per cent: seeds are tried in turn (docs/board.md). The caller reserves the
// .bin before the tools run (an OutputSet) and commits it on success.
#pragma once
#include <optional>
#include <string>
#include <vector>

#include "boards.h"

namespace ncinterp::bitstream {

// A board (sc_model/board/boards.h: part, clock, the interpolator's configuration) and
// where its tools' inputs are.
struct BoardTarget {
  board::Board board;
  std::vector<std::string> pnr_args;  // --hx1k --package tq144
  std::string pcf;                    // rtl/board/<name>.pcf
  double clock_mhz() const { return board.clock_hz / 1e6; }
};

// The boards this build knows; throws std::invalid_argument for another name.
BoardTarget board_target(const std::string& name);

struct BitstreamResult {
  // kDesign: the design does not fit the part or misses the board clock; kTool: a tool
  // could not be run or failed.
  enum class Failure { kNone, kDesign, kTool };
  Failure failure = Failure::kNone;
  bool ok() const { return failure == Failure::kNone; }
  std::optional<unsigned> logic_cells, logic_cells_available;
  std::optional<double> fmax_mhz;
  std::string message;  // the verdict in one line (why it failed, or the summary)
  std::string work_dir;
};

// Writes the bitstream for the board to bin_path; the tools' logs go to work_dir
// (created). Placement seeds 1..seeds are tried in turn until one meets the board clock.
BitstreamResult build_bitstream(const BoardTarget& board, const std::string& bin_path,
                                const std::string& work_dir, unsigned seeds = 5);

}  // namespace ncinterp::bitstream
