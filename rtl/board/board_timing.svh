// Static configuration of board_core computed from a board's clock and the user's
// parameters (included by board_top.sv): UART bit time and step pulse timing in clocks.
// ns values round up to whole clocks, so every time is at least what was asked for.
function automatic logic [15:0] ns_to_cycles(input int ns, input int clock_hz);
  longint c;
  c = (longint'(ns) * longint'(clock_hz) + 64'd999_999_999) / 64'd1_000_000_000;
  ns_to_cycles = c < 1 ? 16'd1 : 16'(c);
endfunction

function automatic logic [15:0] baud_to_cycles(input int baud, input int clock_hz);
  baud_to_cycles = 16'((longint'(clock_hz) + longint'(baud) / 2) / longint'(baud));
endfunction
