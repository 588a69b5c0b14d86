// The boards' operator panel as both languages see it (rtl/board/operator_pins.sv, its
// twin OperatorPinsModel and board-sim's presses): the buttons' debounce sample period.
// interp_pkg_gen writes it into rtl/0_interp_pkg.sv (OperatorDebounceWidth), board_core's
// default, so the board and its simulation cannot disagree on how long a press lasts.
#pragma once

namespace ncinterp {

// The buttons are sampled every 2^kOperatorDebounceWidth clocks (5.5 ms at 12 MHz).
constexpr unsigned kOperatorDebounceWidth = 16;

}  // namespace ncinterp
