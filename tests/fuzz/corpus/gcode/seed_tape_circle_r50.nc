%
(ncinterp example: a circle of radius 50 mm, centre 50 mm left of the start, as four)
(G03 quadrant blocks at 1000 mm/min; each quadrant takes 1/F = 1/12.732 min = 4.71 s)
G17 G21 G91 G93
N1 G03 X-50.000 Y50.000 I-50.000 J0.000 F12.732
N2 G03 X-50.000 Y-50.000 I0.000 J-50.000 F12.732
N3 G03 X50.000 Y-50.000 I50.000 J0.000 F12.732
N4 G03 X50.000 Y50.000 I0.000 J50.000 F12.732
M02
%
