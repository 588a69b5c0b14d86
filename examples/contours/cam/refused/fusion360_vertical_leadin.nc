%
O1003 (PLATE VERTICAL LEAD-IN)
(Written in the style of Fusion 360's generic Fanuc post, for ncinterp's tests)
(2D Contour with the default vertical lead-in and lead-out radius: XZ arcs)
(T1 D=3. CR=0. - ZMIN=-1. - FLAT END MILL)
N10 G90 G94 G17 G91.1
N15 G21
N20 G28 G91 Z0.
N25 G90
N30 T1 M6
N35 S12000 M3
N40 G54
N45 G0 X1. Y0.
N50 G43 Z15. H1
N55 G0 Z5.
N60 G1 Z2. F1000.
N65 G18 G3 X4. Z-1. I3. K0. F600.
N70 G17 G1 X56.
N75 G3 X60. Y4. I0. J4.
N80 G1 Y36.
N85 G3 X56. Y40. I-4. J0.
N90 G1 X4.
N95 G3 X0. Y36. I0. J-4.
N100 G1 Y4.
N105 G3 X4. Y0. I4. J0.
N110 G18 G3 X7. Z2. I0. K3.
N115 G17 G0 Z15.
N120 M5
N125 M30
%
