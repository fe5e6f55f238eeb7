// Test fixture: examples/AxiDrawInterface reporting EBB firmware 2.5.2, so clients take their
// older XM path (no LM before 2.5.3, no SR before 2.6.0).

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
Eibotboard axidraw;

void setup() {
  output_a.begin(OUTPUT_A);
  output_b.begin(OUTPUT_B);
  output_c.begin(OUTPUT_C);
  enable_drivers();

  // AxiDraw belts: 80 microsteps per mm; +x right and +y down the page, as the EBB moves them.
  channel_a.begin(&output_a, SIGNAL_E);
  channel_a.set_ratio(25.4, 2032);
  channel_a.invert_output();  // +x from motor A towards motor B
  channel_b.begin(&output_b, SIGNAL_E);
  channel_b.set_ratio(25.4, 2032);
  channel_b.invert_output();  // +y away from the long axis
  // The pen servo: the EBB's z is in mm with 50 servo steps (µs of pulse width) per mm.
  channel_z.begin(&output_c, SIGNAL_E);
  channel_z.set_ratio(1, 50);

  encoder_1.begin(ENCODER_1);
  encoder_1.set_ratio(24, 2400);  // one 2400-count turn = 24 mm
  encoder_1.invert();
  encoder_1.output.map(&axidraw_kinematics.input_x);
  encoder_2.begin(ENCODER_2);
  encoder_2.set_ratio(24, 2400);
  encoder_2.invert();
  encoder_2.output.map(&axidraw_kinematics.input_y);

  axidraw.set_version_string("EBBv13_and_above EB Firmware Version 2.5.2");
  axidraw.begin(&Serial);
  axidraw.output_x.map(&axidraw_kinematics.input_x);
  axidraw.output_y.map(&axidraw_kinematics.input_y);
  axidraw.output_z.map(&channel_z.input_target_position);

  axidraw_kinematics.begin();
  axidraw_kinematics.output_a.map(&channel_a.input_target_position);
  axidraw_kinematics.output_b.map(&channel_b.input_target_position);

  dance_start();
}

void loop() { dance_loop(); }
