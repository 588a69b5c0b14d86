%
(ncinterp example part: plate 80 x 70 mm with convex corner arcs, a concave notch)
(and a round hole; outline counter-clockwise, hole clockwise: the part is on the)
(left of both, so the cutter goes --side right)
N10 G17 G21 G90 G94
N20 G0 X0 Y0
N30 G1 X60 Y0 F600
N40 G3 X80 Y20 I0 J20          (convex corner, centre I/J)
N50 G1 X80 Y50
N60 G3 X60 Y70 R20             (convex corner, radius R)
N70 G1 X45 Y70
N80 G2 X25 Y70 I-10 J0         (concave notch)
N90 G1 X0 Y70
N100 G1 X0 Y0
N110 G0 X50 Y35
N120 G2 X50 Y35 I-10 J0        (hole: full circle, clockwise)
N130 M30
%
