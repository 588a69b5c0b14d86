// The boards (see boards.h).
#include "boards.h"

#include <stdexcept>

namespace ncinterp::board {

const std::vector<Board>& boards() {
  // The iCEstick's FTDI channel B has CTS wired; the iCEBreaker's has only RX and TX. The
  // iCEstick's HX1K has room for neither arcs nor the M words (docs/board.md).
  static const std::vector<Board> list = {
      {"icestick", "HX1K", "--hx1k", "tq144", 12e6, false, false, "rtscts", Arch::kSerial, false, false},
      {"icebreaker", "UP5K", "--up5k", "sg48", 12e6, true, true, "xonxoff", Arch::kSerial, true, true},
  };
  return list;
}

std::string board_names() {
  std::string s;
  for (const Board& b : boards()) s += (s.empty() ? "" : ", ") + b.name;
  return s;
}

const Board& board_named(const std::string& name) {
  for (const Board& b : boards())
    if (b.name == name) return b;
  throw std::invalid_argument("unknown board '" + name + "' (" + board_names() + ")");
}

InterpConfig board_interp_config(const Board& b, double clock_hz) {
  InterpConfig cfg = interp_config(clock_hz);
  cfg.arch = b.arch;
  cfg.circle_mode = b.circle_mode;
  cfg.misc_functions = b.misc_functions;
  // board_core's PosWidth, SeqWidth, OffsetWidth (its status line sends their low bits).
  cfg.pos_width = cfg.seq_width = cfg.offset_width = 20;
  return cfg;
}

}  // namespace ncinterp::board
