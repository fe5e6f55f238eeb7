// Damped pendulum on an encoder shaft.
#include "models/damped_pendulum.hpp"

#include <cmath>

namespace stepdance::sim {
namespace {
constexpr double kPi = 3.14159265358979323846;
}  // namespace

DampedPendulum::DampedPendulum(const PendulumSettings& settings)
    : settings_(settings), edges_at_start_(edges_below(angle_rad_at(0))) {}

double DampedPendulum::angle_rad_at(SimTime time) const {
  const double amplitude_rad = settings_.amplitude_deg * kPi / 180.0;
  if (time <= settings_.release) return amplitude_rad;
  const double since_s = to_seconds(time - settings_.release);
  return amplitude_rad * std::exp(-since_s / settings_.decay_s) * std::cos(2.0 * kPi * since_s / settings_.period_s);
}

int64_t DampedPendulum::edges_below(double angle_rad) const {
  return static_cast<int64_t>(std::floor(angle_rad * static_cast<double>(counts_per_revolution()) / (2.0 * kPi)));
}

int64_t DampedPendulum::count_at(SimTime time) const { return edges_below(angle_rad_at(time)) - edges_at_start_; }

}  // namespace stepdance::sim
