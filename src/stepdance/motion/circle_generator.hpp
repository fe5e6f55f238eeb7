// CircleGenerator: a point going round a circle, driven by time or by an input.
#pragma once

#include "stepdance/core/block.hpp"
#include "stepdance/core/block_port.hpp"
#include "stepdance/core/status.hpp"
#include "stepdance/core/units.hpp"
#include "stepdance/motion/angle_source.hpp"
#include "stepdance/motion/trig_memo.hpp"

namespace stepdance {

/// Moves (output_x, output_y) round a circle of `radius` counter-clockwise from where it starts:
/// x = r·sin θ, y = r·(1 − cos θ). The angle advances by rotational_speed_rev_per_sec × 40 µs
/// per frame after setNoInput(), else by that rate × the change of `input` per frame.
///
/// Units, as the original library had them: despite its name rotational_speed_rev_per_sec is an
/// angular rate in rad/s (rad per input unit with an input) — kept, so sketches draw what their
/// authors saw (6 ≈ 0.95 turns a second). Each frame moves by r·(sin θ₁ − sin θ₀),
/// r·(cos θ₀ − cos θ₁): exact for a steady radius (the circle closes after any number of turns),
/// and continuous when the radius changes (the centre moves instead of the pen jumping).
class CircleGenerator : public Block {
 public:
  /// The class name, for reports. Context: any.
  const char* type_name() const override { return "CircleGenerator"; }
  /// Begins the ports and registers in the pre-channel stage. Context: loop.
  Status begin();
  /// The angle advances with time instead of the input. Context: loop.
  void setNoInput() { no_input_ = true; }
  /// After setNoInput(): limits how fast the angular rate (rotational_speed_rev_per_sec) may change, rad/s², so a
  /// jump of the knob that sets it makes the motion speed up or slow down smoothly; 0 (default)
  /// = no limit. Context: any.
  void set_angular_acceleration(double rad_per_s2) { angle_.set_angular_acceleration(rad_per_s2); }
  /// The angle, radians in [0, 2π). Context: any.
  double angle() const { return angle_.angle(); }
  void debugPrint() {}
  /// One frame. Context: frame ISR.
  void run() override;

  BlockPort input;
  BlockPort output_x;
  BlockPort output_y;
  /// Radius, output world units. Context: any.
  ControlParameter radius = 1.0f;
  /// Angular rate: rad/s (or rad per input unit), see above. Context: any.
  ControlParameter rotational_speed_rev_per_sec = 6.0f;

 private:
  AngleSource angle_;
  TrigMemo trig_;
  bool no_input_ = false;
  DecimalPosition input_state_ = 0;
  DecimalPosition x_ = 0;
  DecimalPosition y_ = 0;
};

}  // namespace stepdance
