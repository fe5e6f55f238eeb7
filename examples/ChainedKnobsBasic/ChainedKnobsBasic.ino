// Chained knobs: a Basic Module turns its two knobs into an X/Y motion stream on OUTPUT A, for a
// Driver Module at the other end of a TRRS cable to draw with (see ../ChainedPlotterDriver).
//
//   ENC1 ─► Encoder ─► channel_x ─► X pulses (2 µs) ┐
//                                                   ├─► OUTPUT A ─► cable ─► Driver's INPUT A
//   ENC2 ─► Encoder ─► channel_y ─► Y pulses (3 µs) ┘
//
// Modules talk at the standard resolution, STANDARD_RATIO_MM: one pulse = 0.01 mm.

#define module_basic
#include "stepdance.hpp"

// The Basic Module's one motion-stream output.
OutputPort output_a;

// One channel per axis; both share the port, each on its own signal.
Channel channel_x;
Channel channel_y;

Encoder encoder_1;
Encoder encoder_2;

void setup() {
  output_a.begin(OUTPUT_A);

  // 0.01 mm of motion = one pulse on the wire.
  channel_x.begin(&output_a, SIGNAL_X);
  channel_x.set_ratio(STANDARD_RATIO_MM);
  channel_y.begin(&output_a, SIGNAL_Y);
  channel_y.set_ratio(STANDARD_RATIO_MM);

  // The knobs of Step-A-Sketch: one 2400-count turn = 24 mm, so one count = one pulse. Inverted
  // like Step-A-Sketch's, so the chained rig draws the way the single-board rig does.
  encoder_1.begin(ENCODER_1);
  encoder_1.set_ratio(24, 2400);
  encoder_1.invert();
  encoder_1.output.map(&channel_x.input_target_position);
  encoder_2.begin(ENCODER_2);
  encoder_2.set_ratio(24, 2400);
  encoder_2.invert();
  encoder_2.output.map(&channel_y.input_target_position);

  dance_start();
}

void loop() { dance_loop(); }
