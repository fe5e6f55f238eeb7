(Inch units, including arcs and offsets given in inches)
G20 G90
G0 X1 Y1
G1 X2 Y1.5 F20
G2 X3 Y1.5 R0.5
G3 X2 Y1.5 I-0.5 J0
G92 X0 Y0
G1 X0.25 Y0.25
G21 G1 X10 Y10
G92.1
G0 X0 Y0
M2
