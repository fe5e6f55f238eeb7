// AxiDraw recorder: draw with the two knobs, record the drawing on the SD card, replay it twice,
// each time shifted to the right.
//
//   D1 (toggle)  pen down / up
//   D2 (toggle)  start / stop recording ("drawing" on the card)
//   A4 (button)  replay the recording twice, each copy 30 mm to the right of the last
//
// The recorder pulls what reaches the kinematics' X and Y inputs and the pen channel, so it
// records the knobs (or anything else driving the pen); the player pushes it back in the same
// places. Our file format keeps each track's resolution: X and Y in 0.01 mm steps, the pen in
// servo steps.
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
Button pen_button;
Button record_button;
Button replay_button;
PositionGenerator pen_position;
PositionGenerator shift_x;
FourTrackRecorder recorder;
FourTrackPlayer player;

constexpr double kPenUpSteps = 200;  // servo steps (1 step = 1 µs of pulse) from neutral
constexpr double kPenDownSteps = -200;
constexpr double kPenSpeedStepsPerS = 2000;
constexpr double kReplayShiftMm = 30;
constexpr double kShiftSpeedMmPerS = 50;
constexpr int kReplays = 2;

enum class Replay { kIdle, kShifting, kPlaying };
Replay replay = Replay::kIdle;
int replays_left = 0;

void pen_down() { pen_position.go(kPenDownSteps, ABSOLUTE, kPenSpeedStepsPerS); }
void pen_up() { pen_position.go(kPenUpSteps, ABSOLUTE, kPenSpeedStepsPerS); }

void start_recording() {
  if (recorder.start("drawing") == stepdance::Status::kOk) Serial.println("recording");
}

void stop_recording() {
  recorder.stop();
  Serial.print("recorded ");
  Serial.print(static_cast<uint32_t>(recorder.current_sample_index / CORE_FRAME_FREQ_HZ));
  Serial.println(" s");
}

void shift_right() {
  shift_x.go(kReplayShiftMm, INCREMENTAL, kShiftSpeedMmPerS);
  replay = Replay::kShifting;
}

void replay_twice() {
  if (replay != Replay::kIdle || recorder.recorder_active) return;
  replays_left = kReplays;
  shift_right();
}

// Runs the replays from the loop: shift, play, shift, play.
void follow_replay() {
  if (replay == Replay::kShifting && shift_x.is_idle()) {
    replay = player.start("drawing") == stepdance::Status::kOk ? Replay::kPlaying : Replay::kIdle;
    --replays_left;
  } else if (replay == Replay::kPlaying && !player.playback_active) {
    if (replays_left > 0) {
      shift_right();
    } else {
      replay = Replay::kIdle;
      Serial.println("replays done");
    }
  }
}

void setup() {
  output_a.begin(OUTPUT_A);
  output_b.begin(OUTPUT_B);
  output_c.begin(OUTPUT_C);
  enable_drivers();

  // Channels and knobs inverted as in the original's AxiDraw sketches: on the real AxiDraw the
  // sketch's x and y are then the paper's.
  channel_a.begin(&output_a, SIGNAL_E);
  channel_a.set_ratio(25.4, 2032);
  channel_a.invert_output();  // +x from motor A towards motor B
  channel_b.begin(&output_b, SIGNAL_E);
  channel_b.set_ratio(25.4, 2032);
  channel_b.invert_output();  // +y away from the long axis
  channel_z.begin(&output_c, SIGNAL_E);

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

  pen_position.output.map(&channel_z.input_target_position);
  pen_position.begin();
  shift_x.output.map(&axidraw_kinematics.input_x);
  shift_x.begin();

  recorder.set_file_format(RECORDING_FORMAT_STEPDANCE);
  recorder.tracks[2].set_resolution(1.0);  // the pen: one servo step per recorded step
  recorder.input_1.map(&axidraw_kinematics.input_x);
  recorder.input_2.map(&axidraw_kinematics.input_y);
  recorder.input_3.map(&channel_z.input_target_position);
  recorder.begin();
  player.output_1.map(&axidraw_kinematics.input_x);
  player.output_2.map(&axidraw_kinematics.input_y);
  player.output_3.map(&channel_z.input_target_position);
  player.begin();

  pen_button.begin(IO_D1, INPUT_PULLDOWN);
  pen_button.set_mode(BUTTON_MODE_TOGGLE);
  pen_button.set_callback_on_press(&pen_down);
  pen_button.set_callback_on_release(&pen_up);
  record_button.begin(IO_D2, INPUT_PULLDOWN);
  record_button.set_mode(BUTTON_MODE_TOGGLE);
  record_button.set_callback_on_press(&start_recording);
  record_button.set_callback_on_release(&stop_recording);
  replay_button.begin(IO_A4, INPUT_PULLDOWN);
  replay_button.set_callback_on_press(&replay_twice);

  pen_up();
  dance_start();
}

void loop() {
  follow_replay();
  dance_loop();
}
