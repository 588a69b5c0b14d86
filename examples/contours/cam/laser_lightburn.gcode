; Written in the style of LightBurn's GRBL (M4) output, for ncinterp's tests
; GRBL device profile, absolute coords
; Bounds: X5 Y5 to X55 Y35
G00 G17 G40 G21 G54
G90
M4
; Cut @ 600 mm/min, 80% power
M8
G0X10Y5
G1X50S800F600
G3X55Y10I0J5
G1Y30
G3X50Y35I-5J0
G1X10
G3X5Y30I0J-5
G1Y10
G3X10Y5I5J0
G1S0
; Cut @ 600 mm/min, 60% power
G0X24Y20
G1X36S600
G1Y24
G1X24
G1Y20
M9
G1S0
M5
G90
; return to user-defined finish pos
G0 X0 Y0
M2
