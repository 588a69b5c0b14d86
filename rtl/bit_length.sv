// Bit length of an unsigned value (position of the highest 1 plus one; 0 for 0).
//
// What: a priority encoder. The line DDA of a block with increments dx, dy runs 2^k
// iterations with k = bit length of max(|dx|, |dy|), which equals the bit length of
// (|dx| | |dy|), so no comparator is needed.
// Timing: purely combinational.
module bit_length #(
  parameter int unsigned Width = 16,
  // Width of the result: enough for the value Width itself.
  parameter int unsigned LengthWidth = $clog2(Width + 1)
) (
  input  logic [Width-1:0]       value_i,
  output logic [LengthWidth-1:0] length_o
);

  always_comb begin
    length_o = '0;
    for (int unsigned b = 0; b < Width; b++) begin
      if (value_i[b]) length_o = LengthWidth'(b + 1);
    end
  end

endmodule
