// Planned drawing: the sketch itself plans a figure — a five-pointed star, then a spiral of
// 1,000 short segments — through a TimeBasedInterpolator on an AxiDraw, while the two knobs nudge
// the pen live and a potentiometer on A1 sets the feed override (centre = 100 %, down = pause,
// up = up to 200 %).
//
//   figure ─► TimeBasedInterpolator ─► x, y ─┬─► CoreXY ─► channels A, B ─► motors
//   ENC1, ENC2 ─► Encoders ─────────► x, y ─┘
//   TimeBasedInterpolator z (mm) ─► channel C (50 steps/mm) ─► pen servo (Z4 up, Z-4 down)
//   A1 potentiometer ─► speed_override (0 … 2)
//
// The planner looks ahead over its queue, so the spiral's 1,000 vertices flow without stopping
// and every corner of the star is taken at the speed its angle allows.

#define module_driver
#include "stepdance.hpp"

#include <math.h>

OutputPort output_a;
OutputPort output_b;
OutputPort output_c;
Channel channel_a;
Channel channel_b;
Channel channel_z;
KinematicsCoreXY axidraw_kinematics;
Encoder encoder_1;
Encoder encoder_2;
AnalogInput feed_knob;
TimeBasedInterpolator planner;

constexpr double kPenUpMm = 4;
constexpr double kPenDownMm = -4;
constexpr double kDrawMmPerS = 60;
constexpr double kTravelMmPerS = 120;
constexpr double kPenMmPerS = 40;
constexpr double kPi = 3.14159265358979;

// The figure as a list of steps, produced one at a time so the planner's queue is never overfilled.
constexpr double kStarCentre[2] = {70, 70};
constexpr double kStarRadius = 50;
constexpr double kSpiralCentre[2] = {200, 100};
constexpr int kSpiralSegments = 1000;
constexpr double kSpiralTurns = 5;
constexpr double kSpiralInner = 5;
constexpr double kSpiralOuter = 60;

int step_index = 0;

void star_point(int k, double& x, double& y) {
  const double angle = kPi / 2 + k * 4 * kPi / 5;  // every second vertex of a pentagon
  x = kStarCentre[0] + kStarRadius * cos(angle);
  y = kStarCentre[1] + kStarRadius * sin(angle);
}

void spiral_point(int k, double& x, double& y) {
  const double fraction = static_cast<double>(k) / kSpiralSegments;
  const double angle = 2 * kPi * kSpiralTurns * fraction;
  const double radius = kSpiralInner + (kSpiralOuter - kSpiralInner) * fraction;
  x = kSpiralCentre[0] + radius * cos(angle);
  y = kSpiralCentre[1] + radius * sin(angle);
}

// Queues step `index` of the figure; false once the figure is complete.
bool queue_step(int index) {
  double x = 0, y = 0;
  if (index == 0) {
    star_point(0, x, y);
    return planner.add_move(ABSOLUTE, kTravelMmPerS, x, y, kPenUpMm, 0, 0, 0) >= 0;
  }
  if (index == 1) return planner.add_move(INCREMENTAL, kPenMmPerS, 0, 0, kPenDownMm - kPenUpMm, 0, 0, 0) >= 0;
  if (index <= 6) {
    star_point(index - 1, x, y);
    return planner.add_move(ABSOLUTE, kDrawMmPerS, x, y, kPenDownMm, 0, 0, 0) >= 0;
  }
  if (index == 7) return planner.add_move(INCREMENTAL, kPenMmPerS, 0, 0, kPenUpMm - kPenDownMm, 0, 0, 0) >= 0;
  if (index == 8) {
    spiral_point(0, x, y);
    return planner.add_move(ABSOLUTE, kTravelMmPerS, x, y, kPenUpMm, 0, 0, 0) >= 0;
  }
  if (index == 9) return planner.add_move(INCREMENTAL, kPenMmPerS, 0, 0, kPenDownMm - kPenUpMm, 0, 0, 0) >= 0;
  if (index <= 9 + kSpiralSegments) {
    spiral_point(index - 9, x, y);
    return planner.add_move(ABSOLUTE, kDrawMmPerS, x, y, kPenDownMm, 0, 0, 0) >= 0;
  }
  if (index == 10 + kSpiralSegments)
    return planner.add_move(INCREMENTAL, kPenMmPerS, 0, 0, kPenUpMm - kPenDownMm, 0, 0, 0) >= 0;
  if (index == 11 + kSpiralSegments) return planner.add_move(ABSOLUTE, kTravelMmPerS, 0, 0, kPenUpMm, 0, 0, 0) >= 0;
  return false;
}

void setup() {
  output_a.begin(OUTPUT_A);
  output_b.begin(OUTPUT_B);
  output_c.begin(OUTPUT_C);
  enable_drivers();

  // AxiDraw belts: 80 microsteps per mm on each motor; inverted as on the real machine, so +x is
  // right and +y down the page. The knobs are inverted as in the original's sketches.
  channel_a.begin(&output_a, SIGNAL_E);
  channel_a.set_ratio(25.4, 2032);
  channel_a.invert_output();  // +x from motor A towards motor B
  channel_b.begin(&output_b, SIGNAL_E);
  channel_b.set_ratio(25.4, 2032);
  channel_b.invert_output();  // +y away from the long axis
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

  planner.begin();
  planner.set_acceleration(1500);           // mm/s² along the path
  planner.limits().use_core_xy(150, 2000);  // each motor: 150 mm/s, 2000 mm/s²
  planner.output_x.map(&axidraw_kinematics.input_x);
  planner.output_y.map(&axidraw_kinematics.input_y);
  planner.output_z.map(&channel_z.input_target_position);

  // Feed override from the pot: 0 at the bottom (a smooth pause), exactly 1 around the centre,
  // 2 at the top.
  feed_knob.begin(IO_A1);
  feed_knob.set_floor(0, 0);
  feed_knob.set_ceiling(2, 1023);
  feed_knob.set_deadband(1, 512, 16);
  feed_knob.map(&planner.speed_override);

  axidraw_kinematics.begin();
  axidraw_kinematics.output_a.map(&channel_a.input_target_position);
  axidraw_kinematics.output_b.map(&channel_b.input_target_position);

  dance_start();
}

void loop() {
  // Keep the planner fed: it plans in dance_loop() and refuses moves (−1) when its queue is full.
  while (!planner.queue_is_full() && queue_step(step_index)) ++step_index;
  dance_loop();
}
