// One axis's half of a circle DDA iteration: integrate the other coordinate, step on carry.
//
// What: the integrator of axis A adds |b|, the magnitude of the other coordinate relative
// to the centre; a carry out of bit k is a step of A, which moves |a| one BLU (up if A's
// magnitude grows along the arc, else down) and uses one of A's remaining pulses. When the
// other axis has no pulses left, bit k-1 of the addend is forced on (at least half a step
// per iteration), so A's last pulses come out even where |b| is 0 (an arc ending on an
// axis). An axis with no pulses left never steps. dda_circle.sv chains two of these per
// iteration, the second seeing the first's new magnitude (immediate update).
// Timing: purely combinational.
module circle_half_step #(
  parameter int Width = 16
) (
  input  logic [Width:0]   kpow_i,        // 2^k of the block (one-hot)
  input  logic [Width-1:0] acc_i,         // A's integrator, < 2^k
  input  logic [Width-1:0] other_mag_i,   // |b|, < 2^k
  input  logic             other_done_i,  // b has no pulses left
  input  logic [Width-1:0] mag_i,         // |a|
  input  logic             grow_i,        // |a| grows at A's steps
  input  logic [Width-1:0] cnt_i,         // A's pulses left
  output logic             step_o,        // A steps in this half-iteration
  output logic [Width-1:0] acc_o,
  output logic [Width-1:0] mag_o,
  output logic [Width-1:0] cnt_o
);

  logic [Width:0] addend, sum;

  always_comb begin
    addend = {1'b0, other_mag_i};
    if (other_done_i) addend = addend | (kpow_i >> 1);
    sum    = {1'b0, acc_i} + addend;  // < 2^(k+1)
    step_o = |(sum & kpow_i) && cnt_i != '0;
    acc_o  = sum[Width-1:0] & ~kpow_i[Width-1:0];  // clearing bit k subtracts 2^k
    mag_o  = mag_i;
    cnt_o  = cnt_i;
    if (step_o) begin
      mag_o = grow_i ? mag_i + 1'b1 : mag_i - 1'b1;
      cnt_o = cnt_i - 1'b1;
    end
  end

endmodule
