// CorexyPlotter: CoreXY forward kinematics and servo pen state.
#include "models/corexy_plotter.hpp"

namespace stepdance::sim {

CorexyPlotter::CorexyPlotter(const StepperDriver& motor_a, const StepperDriver& motor_b, ServoBoard* pen_servo,
                             const CorexySettings& settings)
    : Machine(settings.trace,
              TravelArea{0, settings.travel_x_mm, 0, settings.travel_y_mm, 1.0 / settings.steps_per_mm}),
      motor_a_(motor_a),
      motor_b_(motor_b),
      pen_servo_(pen_servo),
      settings_(settings) {
  set_power_on_pen(PenPoint{settings.start_x_mm, settings.start_y_mm});
}

Machine::Sample CorexyPlotter::sample(SimTime time) {
  a_mm_ = static_cast<double>(motor_a_.position_steps()) / settings_.steps_per_mm;
  b_mm_ = static_cast<double>(motor_b_.position_steps()) / settings_.steps_per_mm;
  Sample now;
  now.pen = PenPoint{settings_.start_x_mm - (a_mm_ + b_mm_) / 2, settings_.start_y_mm - (a_mm_ - b_mm_) / 2};
  now.down = pen_servo_ == nullptr || pen_servo_->pulse_width_us_at(time) < settings_.pen_down_below_us;
  return now;
}

std::optional<double> CorexyPlotter::axis_mm(MachineAxis axis) const { return pen_axis_mm(axis); }

}  // namespace stepdance::sim
