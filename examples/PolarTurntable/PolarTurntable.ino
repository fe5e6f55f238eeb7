// Polar "virtual turntable" on an AxiDraw: the foot pedal on A1 sets how fast a virtual table
// turns, the hand lever on ENC1 sets how far from its centre the pen sits. Hold the pedal and
// pull the lever slowly: the pen draws a spiral. The button on D1 lifts and lowers the pen.
//
//   A1 pedal ─► VelocityGenerator (rad/s) ─► Polar.angle ┐                ┌─► CoreXY.x ┐
//   ENC1 lever ─► Encoder (mm) ──────────► Polar.radius ┴─ x = r cos θ ──┤            ├─► A, B
//                                                           y = r sin θ   └─► CoreXY.y ┘
//   two PositionGenerators carry the table's centre to (100, 100) mm once, at start.

#define module_driver
#include "stepdance.hpp"

OutputPort output_a;
OutputPort output_b;
OutputPort output_c;
Channel channel_a;
Channel channel_b;
Channel channel_z;
KinematicsPolarToCartesian polar_kinematics;
KinematicsCoreXY axidraw_kinematics;
AnalogInput pedal;
Encoder lever;
VelocityGenerator table_speed;
PositionGenerator centre_x;
PositionGenerator centre_y;
PositionGenerator pen_position;
Button button_d1;

// The AxiDraw's channels are inverted, as on the real machine (and in every AxiDraw sketch of the
// original library), so the kinematics' +x and +y are the page's: the centre is (100, 100) mm.
constexpr double kCentreMm = 100;
constexpr double kCentreSpeedMmPerS = 50;
constexpr float kOneTurnPerSecondRadPerS = TWO_PI;  // the pedal fully down
constexpr double kPenUpSteps = 200;                 // servo steps from neutral
constexpr double kPenDownSteps = -200;
constexpr double kPenSpeedStepsPerS = 2000;

void pen_down() { pen_position.go(kPenDownSteps, ABSOLUTE, kPenSpeedStepsPerS); }
void pen_up() { pen_position.go(kPenUpSteps, ABSOLUTE, kPenSpeedStepsPerS); }

void setup() {
  output_a.begin(OUTPUT_A);
  output_b.begin(OUTPUT_B);
  output_c.begin(OUTPUT_C);
  enable_drivers();

  channel_a.begin(&output_a, SIGNAL_E);
  channel_a.set_ratio(25.4, 2032);  // AxiDraw: 80 steps/mm
  channel_a.invert_output();
  channel_b.begin(&output_b, SIGNAL_E);
  channel_b.set_ratio(25.4, 2032);
  channel_b.invert_output();
  channel_z.begin(&output_c, SIGNAL_E);

  // The table's angle: radians, advancing at the pedal's speed.
  table_speed.begin();
  table_speed.output.map(&polar_kinematics.input_angle);

  // The lever: one 2400-count turn = 24 mm of radius.
  lever.begin(ENCODER_1);
  lever.set_ratio(24, 2400);
  lever.output.map(&polar_kinematics.input_radius);

  polar_kinematics.output_x.map(&axidraw_kinematics.input_x);
  polar_kinematics.output_y.map(&axidraw_kinematics.input_y);
  polar_kinematics.begin();

  centre_x.output.map(&axidraw_kinematics.input_x);
  centre_x.begin();
  centre_y.output.map(&axidraw_kinematics.input_y);
  centre_y.begin();

  axidraw_kinematics.output_a.map(&channel_a.input_target_position);
  axidraw_kinematics.output_b.map(&channel_b.input_target_position);
  axidraw_kinematics.begin();

  pedal.set_floor(0, 0);
  pedal.set_ceiling(kOneTurnPerSecondRadPerS, 1023);
  pedal.map(&table_speed.speed_units_per_sec);
  pedal.begin(IO_A1);

  pen_position.output.map(&channel_z.input_target_position);
  pen_position.begin();
  button_d1.begin(IO_D1, INPUT_PULLDOWN);
  button_d1.set_mode(BUTTON_MODE_TOGGLE);
  button_d1.set_callback_on_press(&pen_down);
  button_d1.set_callback_on_release(&pen_up);

  dance_start();
  centre_x.go(kCentreMm, ABSOLUTE, kCentreSpeedMmPerS);
  centre_y.go(kCentreMm, ABSOLUTE, kCentreSpeedMmPerS);
}

void loop() { dance_loop(); }
