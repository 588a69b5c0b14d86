(The minimal case of two depths with tabs: passes at Z-1 and Z-2 over one line)
G21 G90
G0 Z5
G0 X0 Y0
G1 Z-1 F100
G1 X60
G1 Z-2
G1 X55
G1 Z-1
G1 X35
G1 Z-2
G1 X0
G0 Z5
M2
