// Step-A-Sketch: an etch-a-sketch on an AxiDraw. Knob 1 moves the pen along X, knob 2 along Y,
// and the button on D1 lifts and lowers the pen.
//
//   ENC1 ─► Encoder ─► CoreXY.x ┐            ┌─► channel A ─► OUTPUT A ─► left motor
//   ENC2 ─► Encoder ─► CoreXY.y ┴─ a = x + y ┤
//                                  b = x − y └─► channel B ─► OUTPUT B ─► right motor
//   D1 button ─► pen up/down ─► PositionGenerator ─► channel C ─► OUTPUT C ─► servo board

#define module_driver
#include "stepdance.hpp"

// Motion-stream outputs to the two stepper drivers and the hobby-servo board.
OutputPort output_a;
OutputPort output_b;
OutputPort output_c;

// One channel per motor: each turns a target position into step pulses.
Channel channel_a;
Channel channel_b;
Channel channel_z;

KinematicsCoreXY axidraw_kinematics;
Encoder encoder_1;
Encoder encoder_2;
Button button_d1;
PositionGenerator pen_position;

// Servo steps (1 step = 1 µs of servo pulse) from neutral for each pen state.
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

  // AxiDraw belts: 200-step motors at 1/16 microstepping, 40 mm per turn = 80 steps/mm.
  channel_a.begin(&output_a, SIGNAL_E);
  // Inverted, as on the original's AxiDraw sketches: +x then runs from motor A towards motor B
  // (left to right) and +y away from the long axis (down the page).
  channel_a.set_ratio(25.4, 2032);
  channel_a.invert_output();
  channel_b.begin(&output_b, SIGNAL_E);
  channel_b.set_ratio(25.4, 2032);
  channel_b.invert_output();
  // The servo board counts raw steps.
  channel_z.begin(&output_c, SIGNAL_E);

  // The engine runs each block after the blocks that feed it, whatever the begin() order.
  encoder_1.begin(ENCODER_1);
  encoder_1.set_ratio(24, 2400);  // one 2400-count turn of the knob = 24 mm
  encoder_1.invert();
  encoder_1.output.map(&axidraw_kinematics.input_x);
  encoder_2.begin(ENCODER_2);
  encoder_2.set_ratio(24, 2400);
  encoder_2.invert();
  encoder_2.output.map(&axidraw_kinematics.input_y);

  axidraw_kinematics.begin();
  axidraw_kinematics.output_a.map(&channel_a.input_target_position);
  axidraw_kinematics.output_b.map(&channel_b.input_target_position);

  pen_position.output.map(&channel_z.input_target_position);
  pen_position.begin();

  // The button toggles: one press lowers the pen, the next press lifts it.
  button_d1.begin(IO_D1, INPUT_PULLDOWN);
  button_d1.set_mode(BUTTON_MODE_TOGGLE);
  button_d1.set_callback_on_press(&pen_down);
  button_d1.set_callback_on_release(&pen_up);

  dance_start();
}

LoopDelay report_delay;

void report() {
  Serial.print("CPU peak load: ");
  Serial.println(stepdance_get_cpu_usage());
}

void loop() {
  report_delay.periodic_call(&report, 1000);
  dance_loop();
}
