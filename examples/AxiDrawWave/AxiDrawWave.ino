// AxiDraw wave: plotter software plots through the emulated EiBotBoard while a foot pedal on A1
// sets the height of a wave drawn across every line, in time with each move (a whole number of
// half-waves per move, so every line still starts and ends where the software put it).
//
//   Eibotboard ─► x, y ──────────────────────────────┬─► CoreXY ─► motors
//        │ direction (Vector2DToAngle) ─► WaveGenerator2D ─┘ (offset across the line)
//        │ move duration ─► MoveDurationToFrequency ─┘
//        │ move progress (0 → 1) ──────────────────────┘
//   A1 pedal ─► wave amplitude (0 … 3 mm)

#define module_driver
#include "stepdance.hpp"

OutputPort output_a;
OutputPort output_b;
OutputPort output_c;
Channel channel_a;
Channel channel_b;
Channel channel_z;
KinematicsCoreXY axidraw_kinematics;
Eibotboard axidraw;
Vector2DToAngle direction;
MoveDurationToFrequency half_waves;
WaveGenerator2D wave;
AnalogInput pedal;

void setup() {
  output_a.begin(OUTPUT_A);
  output_b.begin(OUTPUT_B);
  output_c.begin(OUTPUT_C);
  enable_drivers();
  channel_a.begin(&output_a, SIGNAL_E);
  channel_a.set_ratio(25.4, 2032);
  channel_a.invert_output();  // +x from motor A towards motor B
  channel_b.begin(&output_b, SIGNAL_E);
  channel_b.set_ratio(25.4, 2032);
  channel_b.invert_output();  // +y away from the long axis
  channel_z.begin(&output_c, SIGNAL_E);
  channel_z.set_ratio(1, 50);

  axidraw.begin(&Serial);
  axidraw.output_x.map(&axidraw_kinematics.input_x);
  axidraw.output_y.map(&axidraw_kinematics.input_y);
  axidraw.output_z.map(&channel_z.input_target_position);

  // The wave: across the direction of travel, a whole number of half-waves per move.
  axidraw.output_parameter.map(&wave.input_t, ABSOLUTE);
  direction.input_x.map(&axidraw.output_x);
  direction.input_y.map(&axidraw.output_y);
  direction.output_theta.map(&wave.input_theta, ABSOLUTE);
  direction.begin();
  half_waves.input_move_duration.map(&axidraw.output_duration, ABSOLUTE);
  half_waves.output_frequency.map(&wave.input_frequency, ABSOLUTE);
  half_waves.target_frequency = 10.0;  // half-waves per second of move
  half_waves.begin();
  wave.output_x.map(&axidraw_kinematics.input_x);
  wave.output_y.map(&axidraw_kinematics.input_y);
  wave.begin();

  pedal.set_floor(0, 0);
  pedal.set_ceiling(3, 1023);  // mm of wave at full pedal
  pedal.map(&wave.amplitude);
  pedal.begin(IO_A1);

  axidraw_kinematics.begin();
  axidraw_kinematics.output_a.map(&channel_a.input_target_position);
  axidraw_kinematics.output_b.map(&channel_b.input_target_position);

  dance_start();
}

void loop() { dance_loop(); }
