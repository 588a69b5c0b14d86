(Exported by FreeCAD)
(Post Processor: grbl_post, written in its style for ncinterp's tests)
(Begin preamble)
G17 G90
G21
(Begin operation: TC: Endmill 3mm)
(Path: TC: Endmill 3mm)
(TC: Endmill 3mm)
(Begin toolchange)
( M6 T1 )
M3 S12000
(Finish operation: TC: Endmill 3mm)
(Begin operation: Helix)
(Path: Helix)
(Helix: a 6 mm bore at X30 Y30, helix radius 1.5, down to Z-2)
G0 Z5.000
G0 X31.500 Y30.000
G0 Z3.000
G1 X31.500 Y30.000 Z0.000 F200.000
G2 X28.500 Y30.000 Z-0.500 I-1.500 J0.000 K0.000 F400.000
G2 X31.500 Y30.000 Z-1.000 I1.500 J0.000 K0.000 F400.000
G2 X28.500 Y30.000 Z-1.500 I-1.500 J0.000 K0.000 F400.000
G2 X31.500 Y30.000 Z-2.000 I1.500 J0.000 K0.000 F400.000
G2 X28.500 Y30.000 Z-2.000 I-1.500 J0.000 K0.000 F400.000
G2 X31.500 Y30.000 Z-2.000 I1.500 J0.000 K0.000 F400.000
G0 Z5.000
(Finish operation: Helix)
(Begin operation: Profile)
(Path: Profile)
(Profile: a disc of radius 20 about X30 Y30, step down 1 mm to Z-2)
(Compensated Tool Path. Diameter: 3.0)
G0 Z5.000
G0 X50.000 Y30.000
G0 Z3.000
G1 X50.000 Y30.000 Z-1.000 F200.000
G2 X10.000 Y30.000 Z-1.000 I-20.000 J0.000 K0.000 F600.000
G2 X50.000 Y30.000 Z-1.000 I20.000 J0.000 K0.000 F600.000
G0 Z3.000
G0 X50.000 Y30.000
G1 X50.000 Y30.000 Z-2.000 F200.000
G2 X10.000 Y30.000 Z-2.000 I-20.000 J0.000 K0.000 F600.000
G2 X50.000 Y30.000 Z-2.000 I20.000 J0.000 K0.000 F600.000
G0 Z5.000
(Finish operation: Profile)
(Begin postamble)
M5
G17 G90
M2
