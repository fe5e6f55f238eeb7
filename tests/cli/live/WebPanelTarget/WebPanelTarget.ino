// The browser test's sketch (tests/cli/live/web_page_test.py): an AxiDraw whose RPC names appear
// in no example, so the test can tell the page built its controls from this sketch's __index__.
//
//   plot_to(x, y)  queue a straight move to (x, y) mm at feed_mm_s; returns planner slots left
//   nib_down()     lower the pen          nib_up()   raise it
//   tally()        count the calls; returns the new count (which tab got which shows the pairing)
//   feed_mm_s      a parameter: the speed of plot_to's moves

#define module_driver
#include "stepdance.hpp"

OutputPort output_a;
OutputPort output_b;
OutputPort output_c;
Channel channel_a;
Channel channel_b;
Channel channel_z;
KinematicsCoreXY kinematics;
TimeBasedInterpolator planner;
PositionGenerator nib;
RPC rpc;

double feed_mm_s = 20;
int tallied = 0;

int plot_to(double x_mm, double y_mm) {
  return planner.add_move(ABSOLUTE, static_cast<float>(feed_mm_s), x_mm, y_mm, 0, 0, 0, 0);
}
void nib_down() { nib.go(-200, ABSOLUTE, 2000); }
void nib_up() { nib.go(200, ABSOLUTE, 2000); }
int tally() { return ++tallied; }

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

  planner.begin();
  planner.output_x.map(&kinematics.input_x);
  planner.output_y.map(&kinematics.input_y);
  nib.output.map(&channel_z.input_target_position);
  nib.begin();
  nib_up();

  kinematics.begin();
  kinematics.output_a.map(&channel_a.input_target_position);
  kinematics.output_b.map(&channel_b.input_target_position);

  rpc.begin(&Serial);
  rpc.enroll("plot_to", plot_to);
  rpc.enroll("nib_down", nib_down);
  rpc.enroll("nib_up", nib_up);
  rpc.enroll("tally", tally);
  rpc.enroll("feed_mm_s", feed_mm_s);
  dance_start();
}

void loop() { dance_loop(); }
