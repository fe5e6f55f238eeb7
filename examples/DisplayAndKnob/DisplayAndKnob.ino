// Display and knob: Step-A-Sketch with the board-mounted OLED and Qwiic Twist on QWIIC1.
// The screen shows the pen's position; the Twist scrolls a menu whose MM/COUNT entry sets how
// far the pen moves per count of the two drawing knobs (click to edit, turn, click to finish).
//
//   ENC1 ─► Encoder ─► CoreXY.x ┐            ┌─► channel A ─► OUTPUT A ─► left motor
//   ENC2 ─► Encoder ─► CoreXY.y ┴─ a = x + y ┤
//                                  b = x − y └─► channel B ─► OUTPUT B ─► right motor
//   D1 button ─► pen up/down ─► PositionGenerator ─► channel C ─► OUTPUT C ─► servo board
//   QWIIC1: OLED (0x3C) ◄─ StatusMenu ◄─ Qwiic Twist (0x3F)

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
PositionGenerator pen_position;

OledDisplay screen;
QwiicTwist twist;
StatusMenu menu;

// How far the pen moves per knob count (mm); the menu changes it.
ControlParameter knob_mm_per_count = 0.01f;

constexpr double kPenUpSteps = 200;
constexpr double kPenDownSteps = -200;
constexpr double kPenSpeedStepsPerS = 2000;

void pen_down() { pen_position.go(kPenDownSteps, ABSOLUTE, kPenSpeedStepsPerS); }
void pen_up() { pen_position.go(kPenUpSteps, ABSOLUTE, kPenSpeedStepsPerS); }

// The pen's position is what the kinematics received, so a new knob ratio does not change it.
// Both channels are inverted, as on the real AxiDraw, so the kinematics' inputs are the page's
// coordinates.
float pen_x_mm() { return static_cast<float>(axidraw_kinematics.input_x.read(ABSOLUTE)); }
float pen_y_mm() { return static_cast<float>(axidraw_kinematics.input_y.read(ABSOLUTE)); }

void set_knob_ratio(float mm_per_count) {
  encoder_1.set_ratio(mm_per_count);
  encoder_2.set_ratio(mm_per_count);
}

void setup() {
  output_a.begin(OUTPUT_A);
  output_b.begin(OUTPUT_B);
  output_c.begin(OUTPUT_C);
  enable_drivers();

  channel_a.begin(&output_a, SIGNAL_E);
  channel_a.set_ratio(25.4, 2032);
  channel_a.invert_output();
  channel_b.begin(&output_b, SIGNAL_E);
  channel_b.set_ratio(25.4, 2032);
  channel_b.invert_output();
  channel_z.begin(&output_c, SIGNAL_E);

  encoder_1.begin(ENCODER_1);
  encoder_1.invert();
  encoder_1.output.map(&axidraw_kinematics.input_x);
  encoder_2.begin(ENCODER_2);
  encoder_2.invert();
  encoder_2.output.map(&axidraw_kinematics.input_y);
  set_knob_ratio(knob_mm_per_count);

  axidraw_kinematics.begin();
  axidraw_kinematics.output_a.map(&channel_a.input_target_position);
  axidraw_kinematics.output_b.map(&channel_b.input_target_position);

  pen_position.output.map(&channel_z.input_target_position);
  pen_position.begin();

  button_d1.begin(IO_D1, INPUT_PULLDOWN);
  button_d1.set_mode(BUTTON_MODE_TOGGLE);
  button_d1.set_callback_on_press(&pen_down);
  button_d1.set_callback_on_release(&pen_up);

  // The screen and the knob on QWIIC1; the menu: position, knob ratio, pen up.
  screen.begin(QWIIC_1);
  twist.begin(QWIIC_1);
  twist.set_color(0, 40, 80);
  menu.begin(&screen, &twist, "STEP-A-SKETCH");
  menu.add_value("X", &pen_x_mm, 2);
  menu.add_value("Y", &pen_y_mm, 2);
  menu.add_parameter("MM/COUNT", &knob_mm_per_count, 0.005f, 0.005f, 0.1f, 3, &set_knob_ratio);
  menu.add_action("PEN UP", &pen_up);

  dance_start();
}

void loop() { dance_loop(); }
