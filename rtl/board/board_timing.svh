// Static configuration of board_core computed from a board's clock and the user's
// parameters (included by board_top.sv): UART bit time and step pulse timing in clocks.
// ns values round up to whole clocks, so every time is at least what was asked for.
// 64-bit arithmetic: ns * clock_hz exceeds 32 bits.
function automatic logic [15:0] ns_to_cycles(input int ns, input int clock_hz);
  logic [63:0] c;
  c = (64'(ns) * 64'(clock_hz) + 64'd999_999_999) / 64'd1_000_000_000;
  ns_to_cycles = c < 64'd1 ? 16'd1 : 16'(c);
endfunction

function automatic logic [15:0] baud_to_cycles(input int baud, input int clock_hz);
  baud_to_cycles = 16'((64'(clock_hz) + 64'(baud) / 64'd2) / 64'(baud));
endfunction
