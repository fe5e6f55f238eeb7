; A five-pointed star and its circumscribed circle, drawn by a G-code sender.
; Z is the pen: Z4 lifts it, Z-4 lowers it (the sketch maps 1 mm of Z to 50 servo steps).
G21 G90 G94
G0 Z4
G0 X60.000 Y100.000
G1 Z-4 F3000
G1 X36.489 Y27.639 F3000
G1 X98.042 Y72.361 F3000
G1 X21.958 Y72.361 F3000
G1 X83.511 Y27.639 F3000
G1 X60.000 Y100.000 F3000
G0 Z4
G0 X100.000 Y60.000
G1 Z-4
G2 X100.000 Y60.000 I-40.000 J0 F2400
G0 Z4
G0 X0 Y0
M2
