// Digital pantograph: move the stylus of a five-bar arm and the AxiDraw copies the drawing. Each
// joint of the arm carries a 40,000-count encoder (right joint on ENC1, left on ENC2);
// KinematicsFiveBarForward turns the two joint angles into the stylus's x and y, and CoreXY
// moves the pen there. The button on D1 lifts and lowers the pen.
//
//   ENC1 right joint ─► Encoder (rad) ─► FiveBarForward.r ┐                 ┌─► CoreXY.x ┐
//   ENC2 left joint ──► Encoder (rad) ─► FiveBarForward.l ┴─ stylus x, y ──┤            ├─► A, B
//                                                                           └─► CoreXY.y ┘
//
// At power-on the arms rest against their stops, −60° (right) and 240° (left): the encoders
// start there. The arm's geometry is the original's pantograph (60, 145.75, 134, 169, 178.3,
// 28.82 mm, 2.9019 rad). As in the original example, both encoders are inverted (they count down
// as the kinematics' angles grow) and so are both channels (the AxiDraw's +x and +y are then the
// page's), so the copy on the page has the stylus's orientation; two PositionGenerators shift it
// 100 mm right and 40 mm up the page at start.

#define module_driver
#include "stepdance.hpp"

OutputPort output_a;
OutputPort output_b;
OutputPort output_c;
Channel channel_a;
Channel channel_b;
Channel channel_z;
KinematicsFiveBarForward pantograph_kinematics;
KinematicsCoreXY axidraw_kinematics;
Encoder encoder_r;
Encoder encoder_l;
Button button_d1;
PositionGenerator pen_position;
PositionGenerator shift_x;
PositionGenerator shift_y;

constexpr double kRightHomeRad = -(60.0 / 360.0) * TWO_PI;
constexpr double kLeftHomeRad = (240.0 / 360.0) * TWO_PI;
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
  channel_a.set_ratio(1, 80);  // 80 steps/mm
  channel_a.invert_output();   // +x from motor A towards motor B
  channel_b.begin(&output_b, SIGNAL_E);
  channel_b.set_ratio(1, 80);
  channel_b.invert_output();  // +y away from the long axis
  channel_z.begin(&output_c, SIGNAL_E);

  encoder_r.begin(ENCODER_1);
  encoder_r.set_ratio(TWO_PI, 40000);  // one turn = 40,000 counts (10,000 lines)
  encoder_r.invert();
  encoder_r.set(kRightHomeRad);
  encoder_r.output.map(&pantograph_kinematics.input_r, ABSOLUTE);
  encoder_l.begin(ENCODER_2);
  encoder_l.set_ratio(TWO_PI, 40000);
  encoder_l.invert();
  encoder_l.set(kLeftHomeRad);
  encoder_l.output.map(&pantograph_kinematics.input_l, ABSOLUTE);

  pantograph_kinematics.begin(60, 145.75, 134, 169, 178.3, 28.82, 2.9019);
  pantograph_kinematics.output_x.map(&axidraw_kinematics.input_x);
  pantograph_kinematics.output_y.map(&axidraw_kinematics.input_y);

  shift_x.output.map(&axidraw_kinematics.input_x);
  shift_x.begin();
  shift_y.output.map(&axidraw_kinematics.input_y);
  shift_y.begin();

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
  shift_x.go(100, ABSOLUTE, 50);
  shift_y.go(-40, ABSOLUTE, 50);
}

void loop() { dance_loop(); }
