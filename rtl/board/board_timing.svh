// Static configuration of board_core computed from a board's clock and the user's
// parameters (shared by the board tops): UART bit time, feed modulus, step pulse timing.
// ns values round up to whole clocks, so every time is at least what was asked for.
function automatic logic [15:0] ns_to_cycles(input longint ns, input longint clock_hz);
  longint c;
  c = (ns * clock_hz + 64'd999_999_999) / 64'd1_000_000_000;
  ns_to_cycles = c < 1 ? 16'd1 : 16'(c);
endfunction

function automatic logic [15:0] baud_to_cycles(input longint baud, input longint clock_hz);
  baud_to_cycles = 16'((clock_hz + baud / 2) / baud);
endfunction
