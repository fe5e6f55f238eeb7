// Wheel print: a clay printer driven like a potter's wheel. The foot pedal on A1 turns the build
// (rad/s), the hand lever on ENC1 sets the wall's radius, Z rises one layer per turn, the knob on
// ENC2 nudges Z up or down (a babystep), and the extruder pushes clay in proportion to the path
// the nozzle travels. Two knobs shape the print: A2 how much clay goes down, A3 how far the wall
// is stretched along X (round at one end, twice as wide at the other).
//
//   A1 pedal ─► VelocityGenerator ─► Polar.angle ─► ScalingFilter1D (layer / 2π) ─┬─► channel Z
//   ENC2 nudge ─► Encoder ────────────────────────────────────────────────────────┘
//   ENC1 lever ─► Encoder ─► Polar.radius
//   Polar.x ─► ScalingFilter1D (× stretch, A3) ─► channel X;   Polar.y ─► channel Y
//   stretched x, Polar.y ─► PathLengthGenerator2D (× clay per mm, A2) ─► channel E
//
// The facts are the original library's `wheelbot` sketch (a clay printer, not a wheeled robot):
// its pins, its steps per mm (X/Y 40, Z 1201, E 70), its 2 mm layers and 4 mm nozzle, its pedal
// and clay-knob ranges, its Z and E channels inverted. Differences: the stretch knob reads 1..2
// (the original's reads 0..100 and X is that many times r cos θ, so its low end flattens the wall
// to a line) and sets only the stretch (the original's also drives the turning speed, overriding
// the pedal); the clay is smoothed like X and Y (the original's lags them by 40 ms); and the
// extruder follows the stretched polar motion, not the channels, so the move to the bed's centre
// at power-on deposits nothing.

#define module_driver
#include "stepdance.hpp"

OutputPort output_a;
OutputPort output_b;
OutputPort output_c;
OutputPort output_d;
Channel channel_x;
Channel channel_y;
Channel channel_z;
Channel channel_e;
KinematicsPolarToCartesian polar_kinematics;
AnalogInput pedal;
AnalogInput clay_knob;
AnalogInput stretch_knob;
Encoder lever;
Encoder layer_nudge;
VelocityGenerator wheel_speed;
ScalingFilter1D z_per_turn;
ScalingFilter1D x_stretch;
PathLengthGenerator2D clay;
PositionGenerator centre_x;
PositionGenerator centre_y;

constexpr double kLayerHeightMm = 2.0;
constexpr double kNozzleDiameterMm = 4.0;
// Clay for a bead one layer high and one nozzle wide, in mm of a nozzle-wide clay column per mm of
// path: (2 mm · 4 mm) / (π · (4 mm)² / 4) = 2/π. The clay knob multiplies it by 0..10.
constexpr double kBeadClayMmPerPathMm =
    kLayerHeightMm * kNozzleDiameterMm / (PI * kNozzleDiameterMm * kNozzleDiameterMm / 4);
constexpr double kMaxClayMultiplier = 10;
constexpr double kMaxWheelRadPerS = 2.75;
constexpr double kBedCentreMm = 110;
constexpr double kCentreSpeedMmPerS = 50;
// The pots' ends: a dead zone of 25 counts at the bottom, 3 at the top (the original's).
constexpr uint16_t kKnobLowAdc = 25;
constexpr uint16_t kKnobHighAdc = 1020;

void begin_channels() {
  channel_x.begin(&output_a, SIGNAL_E);
  channel_x.set_ratio(1, 40);       // 40 steps/mm
  channel_x.enable_filtering(200);  // 200 frames: an 8 ms smoothing of stretch-knob jumps
  channel_y.begin(&output_b, SIGNAL_E);
  channel_y.set_ratio(1, 40);
  channel_y.enable_filtering(200);  // the same lag as X, so a circle stays round
  channel_z.begin(&output_c, SIGNAL_E);
  channel_z.set_ratio(1, 1201);  // 1201 steps/mm lead screw
  channel_z.invert_output();     // as the original: its printer's Z and E motors turn the other way
  channel_e.begin(&output_d, SIGNAL_E);
  channel_e.set_ratio(1, 70);  // 70 steps per mm of clay
  channel_e.invert_output();
  channel_e.enable_filtering(200);  // the nozzle's lag, so the clay keeps pace with it
}

void begin_wheel() {
  wheel_speed.begin();
  wheel_speed.output.map(&polar_kinematics.input_angle);

  lever.begin(ENCODER_1);
  lever.set_ratio(1, 2400);  // 1 mm of radius per 2400-count turn
  lever.output.map(&polar_kinematics.input_radius);

  polar_kinematics.output_x.map(&x_stretch.input);
  polar_kinematics.output_y.map(&channel_y.input_target_position);
  polar_kinematics.begin();

  x_stretch.begin(ABSOLUTE);  // X = stretch × r cos θ: a turned knob reshapes the whole wall
  x_stretch.output.map(&channel_x.input_target_position);
}

void begin_layers() {
  z_per_turn.begin();
  z_per_turn.set_ratio(kLayerHeightMm, TWO_PI);  // mm per radian
  z_per_turn.input.map(&polar_kinematics.input_angle);
  z_per_turn.output.map(&channel_z.input_target_position);

  layer_nudge.begin(ENCODER_2);
  layer_nudge.set_ratio(1, 2400);  // 1 mm of Z per 2400-count turn
  layer_nudge.output.map(&channel_z.input_target_position);
}

void begin_clay() {
  clay.begin();
  clay.set_ratio(0);
  clay.input_1.map(&x_stretch.output);
  clay.input_2.map(&polar_kinematics.output_y);
  clay.output.map(&channel_e.input_target_position);
}

void begin_centre() {
  centre_x.output.map(&channel_x.input_target_position);
  centre_x.begin();
  centre_y.output.map(&channel_y.input_target_position);
  centre_y.begin();
}

void begin_knobs() {
  pedal.set_floor(0, kKnobLowAdc);
  pedal.set_ceiling(kMaxWheelRadPerS, kKnobHighAdc);  // rad/s
  pedal.map(&wheel_speed.speed_units_per_sec);
  pedal.begin(IO_A1);
  clay_knob.set_floor(0, kKnobLowAdc);  // clay mm per path mm: 0..10 beads
  clay_knob.set_ceiling(kMaxClayMultiplier * kBeadClayMmPerPathMm, kKnobHighAdc);
  clay_knob.map(&clay.ratio);
  clay_knob.begin(IO_A2);
  stretch_knob.set_floor(1, kKnobLowAdc);  // X per r cos θ
  stretch_knob.set_ceiling(2, kKnobHighAdc);
  stretch_knob.map(&x_stretch.ratio);
  stretch_knob.begin(IO_A3);
}

void setup() {
  output_a.begin(OUTPUT_A);
  output_b.begin(OUTPUT_B);
  output_c.begin(OUTPUT_C);
  output_d.begin(OUTPUT_D);
  enable_drivers();

  begin_channels();
  begin_wheel();
  begin_layers();
  begin_clay();
  begin_centre();
  begin_knobs();

  dance_start();
  centre_x.go(kBedCentreMm, ABSOLUTE, kCentreSpeedMmPerS);
  centre_y.go(kBedCentreMm, ABSOLUTE, kCentreSpeedMmPerS);
}

void loop() { dance_loop(); }
