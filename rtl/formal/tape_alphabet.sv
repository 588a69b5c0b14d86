// The frames a formal harness lets the solver choose (docs/verification.md 10.1): every
// byte, or with Restrict = 1 the characters a program is made of, each with either parity
// bit: % ( ) - . LF 0 1 2 3 F G I J M N X Y.
//
// Idea: the BMCs over the tape decoder (tape_decoder_props, interp_top_props) are slow
// because the solver branches over 256 bytes per frame, most of which the decoder treats
// alike (an unknown character, a parity error). The restricted stream still reaches every
// block kind (line, both arcs, comments, the end, a second N), every error class that
// matters to the handshakes (parity, syntax, unsupported code, block after end, truncated
// tape) and every state of the decoder, so the CI proofs use it; the any-byte proofs run
// behind NCINTERP_FORMAL_SLOW / scripts/formal.sh --only. The point is needed even with no
// fraction digits: an X Y I J or F word is complete only after it. The covers check that
// the restriction leaves blocks reachable (without the point, none was). Not part of the
// design.
module tape_alphabet #(
  parameter bit Restrict = 1'b0
) (
  input  logic [7:0] frame_i,
  output logic       allowed_o
);
  logic [6:0] ch;
  assign ch = frame_i[6:0];
  assign allowed_o = !Restrict ||
      ch == interp_pkg::ChPercent || ch == interp_pkg::ChOpen || ch == interp_pkg::ChClose ||
      ch == interp_pkg::ChMinus || ch == interp_pkg::ChDot || ch == interp_pkg::ChLf ||
      (ch >= interp_pkg::ChZero && ch <= interp_pkg::ChZero + 7'd3) ||
      ch == interp_pkg::ChF || ch == interp_pkg::ChG || ch == interp_pkg::ChI ||
      ch == interp_pkg::ChJ || ch == interp_pkg::ChM || ch == interp_pkg::ChN ||
      ch == interp_pkg::ChX || ch == interp_pkg::ChY;
endmodule
