// Web control: an AxiDraw steered from a web page. `stepdance serve /dev/ttyACM0` (or
// `stepdance serve examples/WebControl` for the simulated plotter) serves a page with a button
// and fields for every name enrolled below; go_to_xy queues a move through the planner, and a
// wave across the direction of travel decorates every line once set_noise_amp makes it high.
//
//   page ─► go_to_xy ─► TimeBasedInterpolator ─► x, y ──────────────────────┬─► CoreXY ─► motors
//                             │ direction (Vector2DToAngle) ─► WaveGenerator2D ─┘ (across the line)
//                             │ move duration ─► MoveDurationToFrequency ─┘
//                             │ move progress (0 → 1) ──────────────────────┘
//                             └─► z ─► pen servo

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
Vector2DToAngle direction;
MoveDurationToFrequency half_waves;
WaveGenerator2D wave;
RPC rpc;

constexpr double kPenUpMm = 4;
constexpr double kPenDownMm = -4;
constexpr float kPenSpeedMmPerS = 40;

// Where the queued moves end, so a pen move keeps x and y and an x/y move keeps the pen.
double target_x_mm = 0;
double target_y_mm = 0;
double target_z_mm = kPenUpMm;

int queue_move(double speed_mm_per_s) {
  return planner.add_move(ABSOLUTE, static_cast<float>(speed_mm_per_s), target_x_mm, target_y_mm, target_z_mm, 0, 0, 0);
}

const char* hello() { return "hello from the AxiDraw"; }
int go_to_xy(double x_mm, double y_mm, double speed_mm_per_s) {
  target_x_mm = x_mm;
  target_y_mm = y_mm;
  return queue_move(speed_mm_per_s);
}
int go_to_xyz(double x_mm, double y_mm, double z_mm, double speed_mm_per_s) {
  target_z_mm = z_mm;
  return go_to_xy(x_mm, y_mm, speed_mm_per_s);
}
int pen_down() {
  target_z_mm = kPenDownMm;
  return queue_move(kPenSpeedMmPerS);
}
int pen_up() {
  target_z_mm = kPenUpMm;
  return queue_move(kPenSpeedMmPerS);
}
void drivers_on() { enable_drivers(); }
void drivers_off() { disable_drivers(); }
// The wave: its height (mm, 0 = straight lines) and half-waves per second of move.
void set_noise_amp(double amplitude_mm) { wave.amplitude = amplitude_mm; }
void set_noise_freq(double half_waves_per_s) { half_waves.target_frequency = half_waves_per_s; }
bool is_idle() { return planner.is_idle(); }

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
  channel_z.set_ratio(1, 50);

  planner.begin();
  planner.output_x.map(&axidraw_kinematics.input_x);
  planner.output_y.map(&axidraw_kinematics.input_y);
  planner.output_z.map(&channel_z.input_target_position);

  // The wave across the direction of travel, a whole number of half-waves per move.
  planner.output_parameter.map(&wave.input_t, ABSOLUTE);
  direction.input_x.map(&planner.output_x);
  direction.input_y.map(&planner.output_y);
  direction.output_theta.map(&wave.input_theta, ABSOLUTE);
  direction.begin();
  half_waves.input_move_duration.map(&planner.output_duration, ABSOLUTE);
  half_waves.output_frequency.map(&wave.input_frequency, ABSOLUTE);
  half_waves.target_frequency = 10.0;
  half_waves.begin();
  wave.amplitude = 0;  // straight lines until the page asks for a wave
  wave.output_x.map(&axidraw_kinematics.input_x);
  wave.output_y.map(&axidraw_kinematics.input_y);
  wave.begin();

  axidraw_kinematics.begin();
  axidraw_kinematics.output_a.map(&channel_a.input_target_position);
  axidraw_kinematics.output_b.map(&channel_b.input_target_position);

  // The pen starts up: the planner begins at z = 0, so the first move lifts it.
  planner.add_move(ABSOLUTE, kPenSpeedMmPerS, 0, 0, kPenUpMm, 0, 0, 0);

  rpc.begin(&Serial);
  rpc.enroll("hello", hello);
  rpc.enroll("go_to_xy", go_to_xy);
  rpc.enroll("go_to_xyz", go_to_xyz);
  rpc.enroll("pen_down", pen_down);
  rpc.enroll("pen_up", pen_up);
  rpc.enroll("drivers_on", drivers_on);
  rpc.enroll("drivers_off", drivers_off);
  rpc.enroll("set_noise_amp", set_noise_amp);
  rpc.enroll("set_noise_freq", set_noise_freq);
  rpc.enroll("is_idle", is_idle);
  rpc.enroll("planner", planner);
  dance_start();
}

void loop() { dance_loop(); }
