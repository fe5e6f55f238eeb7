// AxiDraw interface: the Driver Module pretends to be the AxiDraw's EiBotBoard, so plotter software
// (the Inkscape AxiDraw extension, the AxiDraw Python API, saxi) plots through it, while the two
// knobs nudge the pen live.
//
//   USB Serial (EBB commands) ─► Eibotboard ─► x, y ─┬─► CoreXY ─► channels A, B ─► motors
//   ENC1, ENC2 ─► Encoders ─────────────────► x, y ─┘
//   Eibotboard z (pen servo) ──────────────────────────► channel C ─► OUTPUT C ─► servo board
//
// To be found by the AxiDraw software on real hardware, the board must also present itself as an
// EiBotBoard over USB (see docs/axidraw.md); in the simulator any program opens its terminal.

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
  // 10 µs frames, the shortest this graph fits (docs/high-speed.md): a channel then takes up to
  // 100,000 steps/s, so every EBB move in 1/16, 1/8 or 1/4 stepping (at most 25,000 steps/s, i.e.
  // 100,000 1/16 steps/s in 1/4) runs at its own speed; at 40 µs the board slows down the 1/8
  // moves faster than 12,500 steps/s (saxi's and the AxiDraw software's fastest) to fit.
  set_frame_period_us(10);
  output_a.begin(OUTPUT_A);
  output_b.begin(OUTPUT_B);
  output_c.begin(OUTPUT_C);
  enable_drivers();

  // AxiDraw belts: 80 microsteps per mm. Inverted, as in the original's axidraw_interface: an
  // EiBotBoard's positive motor step is DIR low here, so +x is right and +y down the page, as the
  // EBB moves them. The knobs are inverted as the original's are.
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
