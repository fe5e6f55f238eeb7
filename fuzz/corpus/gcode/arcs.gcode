(Arcs in every plane and both forms, helical moves and a full circle)
G21 G90 G17 G94
G0 X10 Y0 Z0
G3 X0 Y10 I-10 J0 F600
G2 X10 Y0 I0 J-10
G2 X20 Y0 R5
G3 X30 Y0 R-5
G2 X30 Y0 I-5 J0 (full circle)
G3 X20 Y10 Z4 I-5 J5 (helix)
G18 G2 Z15 X20 I0 K5.5
G19 G3 Y20 Z5 J5 K-5
G17 G0 X0 Y0 Z0
G2 X4 Y4 R4
G3 X8 Y0 R4
M2
