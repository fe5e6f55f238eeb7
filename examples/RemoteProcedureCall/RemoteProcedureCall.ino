// Remote procedure calls: a laptop drives the AxiDraw over USB Serial — Python (clients/python),
// a terminal, or any program that writes JSON lines — while the knobs still nudge the pen.
//
//   {"name": "go_to_xy", "args": [50, 40, 30]}   → moves the pen to (50, 40) mm at 30 mm/s
//   {"name": "pen_down"} / {"name": "pen_up"}
//   {"name": "planner.speed_override", "args": [0.5]}   → a parameter of an enrolled block
//   {"name": "__index__"}                         → every enrolled name
//
// From Python:  board = stepdance_rpc.Board(port); board.go_to_xy(50, 40, 30)

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
TimeBasedInterpolator planner;
PositionGenerator pen;
RPC rpc;

constexpr double kPenUpSteps = 200;
constexpr double kPenDownSteps = -200;

// Queues a straight move to (x, y) mm at speed mm/s; returns the planner slots left (−1: full).
int go_to_xy(double x_mm, double y_mm, double speed_mm_per_s) {
  return planner.add_move(ABSOLUTE, static_cast<float>(speed_mm_per_s), x_mm, y_mm, 0, 0, 0, 0);
}
void pen_down() { pen.go(kPenDownSteps, ABSOLUTE, 2000); }
void pen_up() { pen.go(kPenUpSteps, ABSOLUTE, 2000); }
bool is_idle() { return planner.is_idle() && pen.is_idle(); }

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

  encoder_1.begin(ENCODER_1);
  encoder_1.set_ratio(24, 2400);
  encoder_1.invert();
  encoder_1.output.map(&axidraw_kinematics.input_x);
  encoder_2.begin(ENCODER_2);
  encoder_2.set_ratio(24, 2400);
  encoder_2.invert();
  encoder_2.output.map(&axidraw_kinematics.input_y);

  planner.begin();
  planner.output_x.map(&axidraw_kinematics.input_x);
  planner.output_y.map(&axidraw_kinematics.input_y);
  pen.output.map(&channel_z.input_target_position);
  pen.begin();
  pen_up();

  axidraw_kinematics.begin();
  axidraw_kinematics.output_a.map(&channel_a.input_target_position);
  axidraw_kinematics.output_b.map(&channel_b.input_target_position);

  rpc.begin(&Serial);
  rpc.enroll("go_to_xy", go_to_xy);
  rpc.enroll("pen_down", pen_down);
  rpc.enroll("pen_up", pen_up);
  rpc.enroll("is_idle", is_idle);
  rpc.enroll("planner", planner);
  rpc.enroll("encoder_1", encoder_1);
  rpc.enroll("encoder_2", encoder_2);
  dance_start();
}

void loop() { dance_loop(); }
