// The decoded block, as the decoder hands it over, the block buffer stores it and the
// player loads it: the one definition of the record (docs/interpolator.md 3.3 and 4).
// Included inside a module that has the parameters IncWidth, SeqWidth and StepWidth and the
// localparam KWidth ($clog2(IncWidth + 1)): tape_decoder.sv fills it, interp_top.sv reads
// it; the buffer stores $bits of it. A package cannot hold it, since its widths are those
// parameters (rtl/0_interp_pkg.sv explains why). Adding a field is one line here, where
// the decoder sets it and where the player uses it.
// Fields: N, motion (an interp_pkg::motion_e code), dx, dy (sign and magnitude), |i|, |j|
// (an arc's start about its centre), S >= 2^StepWidth, k (a line's bit length of
// max(|dx|, |dy|), an arc's circle DDA k), for an arc the growth of |x| and |y|, and S
// (last: the buffer shows the playing block's low bits to the feed generator).
typedef struct packed {
  logic [SeqWidth-1:0]                n;
  logic [interp_pkg::MotionWidth-1:0] motion;
  logic                               dx_neg;
  logic [IncWidth-1:0]                dx;
  logic                               dy_neg;
  logic [IncWidth-1:0]                dy;
  logic [IncWidth-1:0]                i;
  logic [IncWidth-1:0]                j;
  logic                               step_over;
  logic [KWidth-1:0]                  k;
  logic                               grow_x;
  logic                               grow_y;
  logic [StepWidth-1:0]               step;
} block_t;
