// Harmonograph: two pendulums swing on the shafts of encoders 1 and 2, a pot scales their swing
// up to 20×, and the AxiDraw draws what they do: x follows pendulum 1, y pendulum 2. As the
// pendulums slow down the figure winds inwards. The button on D1 lifts and lowers the pen.
//
//   ENC1 pendulum ─► Encoder ─► ScalingFilter2D.input_1 ─► output_1 ─► CoreXY.x ┐    ┌─► A
//   ENC2 pendulum ─► Encoder ─► ScalingFilter2D.input_2 ─► output_2 ─► CoreXY.y ┴────┴─► B
//   A1 pot ─► ScalingFilter2D.ratio (0 … 20, 1 around the middle)
//
// Two PositionGenerators carry the pen to its start once, at power-on, so the figure lands on
// the page; on the real machine you would park the pen by hand.

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
AnalogInput in_scale;
PositionGenerator pen_position;
PositionGenerator start_x;
PositionGenerator start_y;
ScalingFilter2D scaling_filter;

// The AxiDraw's channels are inverted, as on the real machine (and in every AxiDraw sketch of the
// original library): the kinematics' +x and +y are then the page's, +x from motor A towards
// motor B and +y away from the long axis. The start is on the page, in mm from the home corner.
// The pendulums are held at the far side of their swing, so from here each one moves the pen
// towards +x or +y only: the figure fills [100, 204.8] × [60, 164.8] mm (see the scenario).
constexpr double kStartXMm = 100;
constexpr double kStartYMm = 60;
constexpr double kStartSpeedMmPerS = 50;
constexpr double kPenUpSteps = 200;
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
  channel_a.set_ratio(25.4, 2032);  // 80 steps/mm
  channel_a.invert_output();        // +x runs from motor A towards motor B
  channel_b.begin(&output_b, SIGNAL_E);
  channel_b.set_ratio(25.4, 2032);
  channel_b.invert_output();  // +y runs away from the long axis
  channel_z.begin(&output_c, SIGNAL_E);

  scaling_filter.begin();  // incremental: each output change = its input's change × ratio
  scaling_filter.output_1.map(&axidraw_kinematics.input_x);
  scaling_filter.output_2.map(&axidraw_kinematics.input_y);

  // The pot: 0 at one end, 20 at the other, exactly 1 in a small band round the middle.
  in_scale.begin(IO_A1);
  in_scale.set_floor(0);
  in_scale.set_ceiling(20);
  in_scale.set_deadband(1, 509, 4);
  in_scale.map(&scaling_filter.ratio);

  encoder_1.begin(ENCODER_1);
  encoder_1.set_ratio(24, 2400);  // 2400 counts a turn = 24 mm
  encoder_1.invert();
  encoder_1.output.map(&scaling_filter.input_1);
  encoder_2.begin(ENCODER_2);
  encoder_2.set_ratio(24, 2400);
  encoder_2.invert();
  encoder_2.output.map(&scaling_filter.input_2);

  start_x.output.map(&axidraw_kinematics.input_x);
  start_x.begin();
  start_y.output.map(&axidraw_kinematics.input_y);
  start_y.begin();

  axidraw_kinematics.begin();
  axidraw_kinematics.output_a.map(&channel_a.input_target_position);
  axidraw_kinematics.output_b.map(&channel_b.input_target_position);

  button_d1.begin(IO_D1, INPUT_PULLDOWN);
  button_d1.set_mode(BUTTON_MODE_TOGGLE);
  button_d1.set_callback_on_press(&pen_down);
  button_d1.set_callback_on_release(&pen_up);
  pen_position.output.map(&channel_z.input_target_position);
  pen_position.begin();

  dance_start();
  start_x.go(kStartXMm, ABSOLUTE, kStartSpeedMmPerS);
  start_y.go(kStartYMm, ABSOLUTE, kStartSpeedMmPerS);
}

void loop() { dance_loop(); }
