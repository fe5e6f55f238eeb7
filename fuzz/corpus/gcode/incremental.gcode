(Incremental distances, a square spiral and mixed modes)
G21 G90
G0 X5 Y5
G91 G1 X10 F1200
Y10
X-10
Y-8
X8
Y6
G3 X-4 Y0 R2
G90 G1 X0 Y0
G91 G0 Z2
G90
M2
