; A triangle for the original's gcode_stepasketch (tests/original_sketches/scenarios/gcode_stepasketch.toml).
; Z is the pen: Z4 lifts it, Z-4 lowers it (channel_z maps 1 mm of Z to 50 servo steps).
G21 G90 G94
G0 Z4
G0 X40 Y40
G1 Z-4 F3000
G1 X100 Y40 F3000
G1 X70 Y90
G1 X40 Y40
G0 Z4
G0 X0 Y0
M2
