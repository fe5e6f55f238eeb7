// Clay-printer texturizer: a spiral vase printed live. The foot pedal on A1 turns the build
// round (rad/s), the hand lever on ENC1 sets the vase's radius, Z rises one layer per turn, and
// the extruder pushes clay in proportion to the path the nozzle travels. Two pots put a wave on
// the radius: A2 its height, A4 how many waves a turn.
//
//   A1 pedal ─► VelocityGenerator ─► Polar.angle ─┬─► ScalingFilter1D (layer / 2π) ─► channel Z
//                                                 └─► WaveGenerator1D ─┐
//   ENC1 lever ─► Encoder ──────────────────────► Polar.radius ◄──────┘
//   Polar.x/y ─► channels X, Y;  Polar.x/y ─► PathLengthGenerator2D (× clay per mm) ─► channel E
//
// Differences from the original's clay_3dprinter_texturizer_modularized_v2: the physical UI
// module's inputs are pots on this board, and the extruder follows the polar motion (not the
// channels), so the move to the bed's centre at power-on deposits nothing.

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
AnalogInput wave_height;
AnalogInput wave_count;
Encoder lever;
VelocityGenerator turn_speed;
ScalingFilter1D z_per_turn;
PathLengthGenerator2D clay;
WaveGenerator1D radius_wave;
PositionGenerator centre_x;
PositionGenerator centre_y;

constexpr double kLayerHeightMm = 2.0;
constexpr double kClayMmPerPathMm = 0.05;
constexpr double kBedCentreMm = 110;

void setup() {
  output_a.begin(OUTPUT_A);
  output_b.begin(OUTPUT_B);
  output_c.begin(OUTPUT_C);
  output_d.begin(OUTPUT_D);
  enable_drivers();

  channel_x.begin(&output_a, SIGNAL_E);
  channel_x.set_ratio(1, 80);  // 80 steps/mm belts
  channel_y.begin(&output_b, SIGNAL_E);
  channel_y.set_ratio(1, 80);
  channel_z.begin(&output_c, SIGNAL_E);
  channel_z.set_ratio(1, 400);  // 8 mm lead screw, 1/16 microsteps
  channel_e.begin(&output_d, SIGNAL_E);
  channel_e.set_ratio(1, 93);  // clay plunger

  turn_speed.begin();
  turn_speed.output.map(&polar_kinematics.input_angle);

  lever.begin(ENCODER_1);
  lever.set_ratio(24, 2400);  // 24 mm of radius per turn of the lever
  lever.output.map(&polar_kinematics.input_radius);

  // A spatial wave on the radius: `frequency` waves per turn of the build.
  radius_wave.input.map(&polar_kinematics.input_angle, INCREMENTAL);
  radius_wave.output.map(&polar_kinematics.input_radius);
  radius_wave.begin();

  polar_kinematics.output_x.map(&channel_x.input_target_position);
  polar_kinematics.output_y.map(&channel_y.input_target_position);
  polar_kinematics.begin();

  z_per_turn.begin();
  z_per_turn.set_ratio(kLayerHeightMm, TWO_PI);
  z_per_turn.input.map(&polar_kinematics.input_angle);
  z_per_turn.output.map(&channel_z.input_target_position);

  clay.begin();
  clay.set_ratio(kClayMmPerPathMm);
  clay.input_1.map(&polar_kinematics.output_x);
  clay.input_2.map(&polar_kinematics.output_y);
  clay.output.map(&channel_e.input_target_position);

  centre_x.output.map(&channel_x.input_target_position);
  centre_x.begin();
  centre_y.output.map(&channel_y.input_target_position);
  centre_y.begin();

  pedal.set_floor(0, 25);
  pedal.set_ceiling(2.75, 1020);  // rad/s
  pedal.map(&turn_speed.speed_units_per_sec);
  pedal.begin(IO_A1);
  wave_height.set_floor(0, 0);
  wave_height.set_ceiling(4, 1023);  // mm
  wave_height.map(&radius_wave.amplitude);
  wave_height.begin(IO_A2);
  wave_count.set_floor(0, 0);
  wave_count.set_ceiling(16, 1023);  // waves per turn
  wave_count.map(&radius_wave.frequency);
  wave_count.begin(IO_A4);

  dance_start();
  centre_x.go(kBedCentreMm, ABSOLUTE, 50);
  centre_y.go(kBedCentreMm, ABSOLUTE, 50);
}

void loop() { dance_loop(); }
