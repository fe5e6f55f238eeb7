// PolarTurntable: table angle and arm radius to paper coordinates.
#include "models/polar_turntable.hpp"

#include <cmath>

namespace stepdance::sim {

namespace {
constexpr double kTwoPi = 6.28318530717958647692;
}  // namespace

PolarTurntable::PolarTurntable(const StepperDriver& angle_motor, const StepperDriver& radius_motor,
                               ServoBoard* pen_servo, const PolarSettings& settings)
    : Machine(settings.trace, std::nullopt),
      angle_motor_(angle_motor),
      radius_motor_(radius_motor),
      pen_servo_(pen_servo),
      settings_(settings) {}

Machine::Sample PolarTurntable::sample(SimTime time) {
  angle_rad_ = kTwoPi * static_cast<double>(angle_motor_.position_steps()) / settings_.steps_per_rev;
  radius_mm_ = static_cast<double>(radius_motor_.position_steps()) / settings_.steps_per_mm;
  Sample now;
  now.pen = PenPoint{radius_mm_ * std::cos(-angle_rad_), radius_mm_ * std::sin(-angle_rad_)};
  now.down = pen_servo_ == nullptr || pen_servo_->pulse_width_us_at(time) < settings_.pen_down_below_us;
  return now;
}

std::optional<double> PolarTurntable::axis_mm(MachineAxis axis) const {
  if (axis == MachineAxis::kX) return radius_mm_;
  return std::nullopt;
}

}  // namespace stepdance::sim
