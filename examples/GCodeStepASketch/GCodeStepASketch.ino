// G-code Step-A-Sketch: a G-code sender (gSender, cncjs, bCNC, UGS…) streams a drawing over USB
// Serial to an AxiDraw while the two knobs nudge the pen live. Both sum at the kinematics.
//
//   USB Serial ─► GCodeInterface ─► x, y ─┬─► CoreXY ─► channels A, B ─► OUTPUT A, B ─► motors
//   ENC1, ENC2 ─► Encoders ──────► x, y ─┘
//   G-code Z (mm) ─────────────────────────► channel C (50 steps/mm) ─► OUTPUT C ─► pen servo
//
// The interface speaks Grbl 1.1: `ok`/`error:N` per line, `?` status, `!` hold, `~` resume,
// Ctrl-X reset, `$$` settings. G0/G1/G2/G3/G4, G20/G21, G90/G91, G92, G54–G59, M2/M30 and more.

#define module_driver
#include "stepdance.hpp"

OutputPort output_a;
OutputPort output_b;
OutputPort output_c;

Channel channel_a;
Channel channel_b;
Channel channel_z;

KinematicsCoreXY axidraw_kinematics;
Encoder encoder_1;
Encoder encoder_2;
GCodeInterface gcode;

void setup() {
  output_a.begin(OUTPUT_A);
  output_b.begin(OUTPUT_B);
  output_c.begin(OUTPUT_C);
  enable_drivers();

  // AxiDraw belts: 80 microsteps per mm on each motor. Inverted, as in the original's AxiDraw
  // sketches, so G-code +X and +Y move the real pen right and down the page, from the home corner.
  // The knobs are inverted as the original's are.
  channel_a.begin(&output_a, SIGNAL_E);
  channel_a.set_ratio(25.4, 2032);
  channel_a.invert_output();  // +x from motor A towards motor B
  channel_b.begin(&output_b, SIGNAL_E);
  channel_b.set_ratio(25.4, 2032);
  channel_b.invert_output();  // +y away from the long axis
  // Pen servo: Z in mm, 50 servo steps per mm (Z4 is up, Z-4 is down).
  channel_z.begin(&output_c, SIGNAL_E);
  channel_z.set_ratio(1, 50);

  encoder_1.begin(ENCODER_1);
  encoder_1.set_ratio(24, 2400);  // one 2400-count turn of the knob = 24 mm
  encoder_1.invert();
  encoder_1.output.map(&axidraw_kinematics.input_x);
  encoder_2.begin(ENCODER_2);
  encoder_2.set_ratio(24, 2400);
  encoder_2.invert();
  encoder_2.output.map(&axidraw_kinematics.input_y);

  gcode.begin(&Serial);
  gcode.output_x.map(&axidraw_kinematics.input_x);
  gcode.output_y.map(&axidraw_kinematics.input_y);
  gcode.output_z.map(&channel_z.input_target_position);
  // `$100`–`$102` (steps/mm) come from the channels X, Y and Z drive: senders see 80, 80 and 50.
  // A plotter's speeds and accelerations:
  gcode.settings().set_from_sketch(110, 6000);  // mm/min
  gcode.settings().set_from_sketch(111, 6000);
  gcode.settings().set_from_sketch(112, 3000);
  gcode.settings().set_from_sketch(120, 2000);  // mm/s²
  gcode.settings().set_from_sketch(121, 2000);
  gcode.settings().set_from_sketch(122, 4000);

  axidraw_kinematics.begin();
  axidraw_kinematics.output_a.map(&channel_a.input_target_position);
  axidraw_kinematics.output_b.map(&channel_b.input_target_position);

  dance_start();
}

void loop() { dance_loop(); }
