// RecorderTrack: whole steps toward the input, with a half-step dead band.
#include "stepdance/recording/recorder_track.hpp"

#include <math.h>

namespace stepdance {

// Default 0.01 world units per recorded step (0.01 mm with the usual mm units); set_resolution()
// changes it before a recording starts.
RecorderTrack::RecorderTrack() { input_target_position.set_ratio(0.01, 1.0); }

void RecorderTrack::begin(Block* parent) { input_target_position.begin(&target_steps_, BLOCKPORT_INPUT, parent); }

void RecorderTrack::set_resolution(double world_units, double per_steps) {
  input_target_position.set_ratio(world_units, per_steps);
}

// Frame context: pulls the upstream position into target_steps_ (in recorded steps).
void RecorderTrack::follow_input() {
  input_target_position.pull();
  input_target_position.update();
}

// Frame context. The track keeps its own whole-step counter and moves it toward the (fractional)
// input, rounding to nearest with a half-step dead band so an input resting between two steps does
// not dither. At most max_steps per frame; the remainder follows in later frames, so nothing is
// lost, only delayed.
int32_t RecorderTrack::step_toward_input(int32_t max_steps) {
  const double distance = target_steps_ - static_cast<double>(counter_);
  if (fabs(distance) <= 0.5) return 0;
  const double whole = floor(fabs(distance) + 0.5);
  const int32_t steps = whole > max_steps ? max_steps : static_cast<int32_t>(whole);
  const int32_t signed_steps = distance > 0 ? steps : -steps;
  counter_ += signed_steps;
  return signed_steps;
}

// Used while not recording: jump the counter to the input so the next recorded frame has no jump.
void RecorderTrack::sync_to_input() { counter_ = static_cast<int64_t>(floor(target_steps_ + 0.5)); }

}  // namespace stepdance
