% vfd enable
(Written in the style of a router post that puts its controller header on the '%' line)
G21 G90 G17
M3 S18000
G0 Z5
G0 X0 Y0
G1 Z-1 F200
G1 X30 F800
G1 Y20
G1 X0
G1 Y0
G0 Z5
M5
M30
%
