// The boards (see boards.h).
#include "boards.h"

#include <stdexcept>

namespace ncinterp::board {

const std::vector<Board>& boards() {
  // The iCEstick's FTDI channel B has CTS wired; the iCEBreaker's has only RX and TX, and
  // its core counts characters (it ACKs the bytes it takes), which lets realtime bytes
  // through while the machine holds. The
  // iCEstick's HX1K has room for neither arcs, the M words nor the feed ramp
  // (docs/board.md); the iCEBreaker ramps at 500 mm/s^2, what a small stepper machine
  // takes (docs/motion-control.md 7).
  static const std::vector<Board> list = {
      {"icestick", "HX1K", "--hx1k", "tq144", 12e6, false, 0, "rtscts", Arch::kSerial, false, false, 0, false},
      {"icebreaker", "UP5K", "--up5k", "sg48", 12e6, true, 0b110, "count", Arch::kSerial, true, true, 500, true},
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

InterpConfig board_interp_config(const Board& b, double clock_hz, double accel_mm_s2, double rapid_mm_min) {
  if (accel_mm_s2 < 0) accel_mm_s2 = b.accel_mm_s2;
  if (accel_mm_s2 > 0 && b.accel_mm_s2 == 0)
    throw std::invalid_argument("--accel: the " + b.name + "'s core is built without the feed ramp (docs/board.md)");
  InterpConfig cfg = interp_config(clock_hz, {}, rapid_mm_min, accel_mm_s2);
  cfg.arch = b.arch;
  cfg.circle_mode = b.circle_mode;
  cfg.misc_functions = b.misc_functions;
  // board_core's PosWidth, SeqWidth, OffsetWidth (its status line sends their low bits).
  cfg.pos_width = cfg.seq_width = cfg.offset_width = 20;
  return cfg;
}

}  // namespace ncinterp::board
