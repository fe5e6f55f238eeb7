// Homing test: an AxiDraw-class plotter whose carriage is wherever it was left finds its X and Y
// limit switches, then draws a 40 mm square at absolute coordinates (20, 20) … (60, 60).
//
// Each axis: fast seek toward the switch, pull off 1 mm, slow approach, pull off again; the
// switch point becomes 0. The square's corners are planner moves in machine coordinates
// (GLOBAL), so where they land on the paper proves the homing.
#define module_driver
#include "stepdance.hpp"

OutputPort output_a;
OutputPort output_b;
OutputPort output_c;
Channel channel_a;
Channel channel_b;
Channel channel_z;
KinematicsCoreXY axidraw_kinematics;
TimeBasedInterpolator planner;
Homing homing;

constexpr float kHomingSpeedMmPerS = 40;
constexpr float kDrawSpeedMmPerS = 20;
constexpr float kPenSpeedStepsPerS = 1000;
constexpr double kPenUp = 0;  // servo steps from neutral (1 step = 1 µs of pulse)
constexpr double kPenDown = -300;

void pen(double steps, double x, double y) { planner.add_move(GLOBAL, kPenSpeedStepsPerS, x, y, steps, 0, 0, 0); }
void line_to(double x, double y) { planner.add_move(GLOBAL, kDrawSpeedMmPerS, x, y, kPenDown, 0, 0, 0); }

void draw_square() {
  Serial.println("homed: drawing the square");
  planner.add_move(GLOBAL, kDrawSpeedMmPerS, 20, 20, kPenUp, 0, 0, 0);
  pen(kPenDown, 20, 20);
  line_to(60, 20);
  line_to(60, 60);
  line_to(20, 60);
  line_to(20, 20);
  pen(kPenUp, 20, 20);
}

void homing_failed() { Serial.println("homing failed: check the switches"); }

void setup() {
  output_a.begin(OUTPUT_A);
  output_b.begin(OUTPUT_B);
  output_c.begin(OUTPUT_C);
  enable_drivers();

  // Both channels inverted, as on the real AxiDraw (and in the original's AxiDraw sketches): the
  // sketch's x and y are then the paper's.
  channel_a.begin(&output_a, SIGNAL_E);
  channel_a.set_ratio(25.4, 2032);
  channel_a.invert_output();  // +x from motor A towards motor B
  channel_b.begin(&output_b, SIGNAL_E);
  channel_b.set_ratio(25.4, 2032);
  channel_b.invert_output();  // +y away from the long axis
  channel_z.begin(&output_c, SIGNAL_E);

  axidraw_kinematics.begin();
  axidraw_kinematics.output_a.map(&channel_a.input_target_position);
  axidraw_kinematics.output_b.map(&channel_b.input_target_position);

  planner.begin();
  planner.output_x.map(&axidraw_kinematics.input_x);
  planner.output_y.map(&axidraw_kinematics.input_y);
  planner.output_z.map(&channel_z.input_target_position);

  // X first, then Y; both switches sit at the low end of their axis.
  homing.add_axis(LIMIT_A, 0, HOMING_DIR_BWD, kHomingSpeedMmPerS, &axidraw_kinematics.input_x);
  homing.add_axis(LIMIT_B, 0, HOMING_DIR_BWD, kHomingSpeedMmPerS, &axidraw_kinematics.input_y);
  homing.set_callback_on_finished(&draw_square);
  homing.set_callback_on_failed(&homing_failed);
  homing.begin();

  dance_start();
  homing.start_homing_routine();
}

void loop() { dance_loop(); }
