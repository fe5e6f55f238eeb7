// What the page may ask of the run itself: pause, resume, speed. The front end paces by it.
#pragma once

namespace stepdance::sim::view {

/// Shared by every page of one run; the front end reads it at each pacing tick.
struct RunControl {
  bool paused = false;
  /// Simulated seconds per wall-clock second; 0 = as fast as possible ("max").
  double speed = 1.0;
};

}  // namespace stepdance::sim::view
