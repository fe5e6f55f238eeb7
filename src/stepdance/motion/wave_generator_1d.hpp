// WaveGenerator1D: a sine wave on one output, driven by time or by an input's travel.
#pragma once

#include "stepdance/core/block.hpp"
#include "stepdance/core/block_port.hpp"
#include "stepdance/core/status.hpp"
#include "stepdance/core/units.hpp"
#include "stepdance/motion/angle_source.hpp"
#include "stepdance/motion/trig_memo.hpp"

namespace stepdance {

/// Adds a wave to `output`: from where it starts, output = amplitude·(sin(θ + phase) − sin phase).
/// θ advances by `frequency` × 40 µs per frame after setNoInput(), else by `frequency` × the
/// change of `input` (a spatial wave: rad per input unit, so a line gets a ripple of wavelength
/// 2π / frequency). `frequency` is an angular rate in rad/s as in the original library.
///
/// Differences from the original: `phase` is a phase in radians (the original added it to the
/// amplitude); each frame moves by amplitude·(sin(θ₁ + φ) − sin(θ₀ + φ)), exact over any number
/// of periods and continuous when the amplitude changes.
class WaveGenerator1D : public Block {
 public:
  /// The class name, for reports. Context: any.
  const char* type_name() const override { return "WaveGenerator1D"; }
  Status begin();
  void setNoInput() { no_input_ = true; }
  /// After setNoInput(): limits how fast the angular rate (frequency) may change, rad/s², so a
  /// jump of the knob that sets it makes the motion speed up or slow down smoothly; 0 (default)
  /// = no limit. Context: any.
  void set_angular_acceleration(double rad_per_s2) { angle_.set_angular_acceleration(rad_per_s2); }
  void debugPrint() {}
  void run() override;

  BlockPort input;
  BlockPort output;
  /// Peak of the wave, output world units. Context: any.
  ControlParameter amplitude = 0;
  /// Phase, radians. Context: any.
  ControlParameter phase = 0;
  /// Angular rate: rad/s, or rad per input unit. Context: any.
  ControlParameter frequency = 8;

 private:
  AngleSource angle_;
  TrigMemo trig_;
  bool no_input_ = false;
  DecimalPosition input_state_ = 0;
  DecimalPosition output_state_ = 0;
};

}  // namespace stepdance
