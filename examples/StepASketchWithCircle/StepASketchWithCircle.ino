// Step-A-Sketch with a circle: the knobs move a point across the page and a CircleGenerator
// keeps the pen turning round it, so every line becomes a chain of loops. The foot pedal on A1
// sets how fast the circle turns; the button on D1 lifts and lowers the pen.
//
//   ENC1 ─► Encoder ─────────────┐
//   CircleGenerator.output_x ────┴─► CoreXY.x ┐            ┌─► channel A ─► OUTPUT A
//   ENC2 ─► Encoder ─────────────┐            ├─ a = x + y ┤
//   CircleGenerator.output_y ────┴─► CoreXY.y ┘  b = x − y └─► channel B ─► OUTPUT B
//   A1 pedal ─► circle speed          D1 button ─► PositionGenerator ─► channel C ─► servo
//
// The circle adds r·(sin θ, 1 − cos θ) to the knobs' point in the kinematics' x and y, which
// are the page's (both channels inverted, as on the real AxiDraw): the centre sits r below the
// point, down the page. Unlike the original's example, the circle feeds the kinematics' x and y,
// not the motors' a and b, so it is round on the page.

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
Button button_d1;
AnalogInput pedal;
PositionGenerator pen_position;
CircleGenerator circle;

constexpr double kPenUpSteps = 200;  // servo steps (1 step = 1 µs of pulse) from neutral
constexpr double kPenDownSteps = -200;
constexpr double kPenSpeedStepsPerS = 2000;
constexpr float kCircleRadiusMm = 5;
constexpr float kTwoTurnsPerSecondRadPerS = 4 * PI;  // the pedal fully down

void pen_down() { pen_position.go(kPenDownSteps, ABSOLUTE, kPenSpeedStepsPerS); }
void pen_up() { pen_position.go(kPenUpSteps, ABSOLUTE, kPenSpeedStepsPerS); }

void setup() {
  output_a.begin(OUTPUT_A);
  output_b.begin(OUTPUT_B);
  output_c.begin(OUTPUT_C);
  enable_drivers();

  // AxiDraw belts: 80 steps/mm.
  channel_a.begin(&output_a, SIGNAL_E);
  channel_a.set_ratio(25.4, 2032);
  channel_a.invert_output();
  channel_b.begin(&output_b, SIGNAL_E);
  channel_b.set_ratio(25.4, 2032);
  channel_b.invert_output();
  channel_z.begin(&output_c, SIGNAL_E);

  // The kinematics begins before the blocks that feed it: the engine runs producers first
  // whatever the begin() order.
  axidraw_kinematics.begin();
  axidraw_kinematics.output_a.map(&channel_a.input_target_position);
  axidraw_kinematics.output_b.map(&channel_b.input_target_position);

  encoder_1.begin(ENCODER_1);
  encoder_1.set_ratio(24, 2400);  // one 2400-count turn of the knob = 24 mm
  encoder_1.invert();
  encoder_1.output.map(&axidraw_kinematics.input_x);
  encoder_2.begin(ENCODER_2);
  encoder_2.set_ratio(24, 2400);
  encoder_2.invert();
  encoder_2.output.map(&axidraw_kinematics.input_y);

  // A 5 mm circle turning with time; its speed (rad/s, the original's member name) is the pedal's.
  circle.radius = kCircleRadiusMm;
  circle.setNoInput();
  circle.output_x.map(&axidraw_kinematics.input_x);
  circle.output_y.map(&axidraw_kinematics.input_y);
  circle.begin();

  pedal.set_floor(0, 0);
  pedal.set_ceiling(kTwoTurnsPerSecondRadPerS, 1023);
  pedal.map(&circle.rotational_speed_rev_per_sec);
  pedal.begin(IO_A1);

  pen_position.output.map(&channel_z.input_target_position);
  pen_position.begin();

  button_d1.begin(IO_D1, INPUT_PULLDOWN);
  button_d1.set_mode(BUTTON_MODE_TOGGLE);
  button_d1.set_callback_on_press(&pen_down);
  button_d1.set_callback_on_release(&pen_up);

  dance_start();
}

void loop() { dance_loop(); }
