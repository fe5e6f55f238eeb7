// Potentiometer: position schedule and 10-bit ADC conversion.
#include "models/potentiometer.hpp"

#include <algorithm>
#include <cmath>
#include <iterator>

namespace stepdance::sim {

namespace {
double clamp_unit(double position) { return std::clamp(position, 0.0, 1.0); }
}  // namespace

Potentiometer::Potentiometer(double initial_position) : initial_position_(clamp_unit(initial_position)) {}

void Potentiometer::set(SimTime time, double position) {
  const auto at = std::upper_bound(settings_.begin(), settings_.end(), time,
                                   [](SimTime t, const Setting& setting) { return t < setting.time; });
  settings_.insert(at, Setting{time, clamp_unit(position)});
}

double Potentiometer::position_at(SimTime time) const {
  const auto after = std::upper_bound(settings_.begin(), settings_.end(), time,
                                      [](SimTime t, const Setting& setting) { return t < setting.time; });
  return after == settings_.begin() ? initial_position_ : std::prev(after)->position;
}

uint16_t Potentiometer::adc_value_at(SimTime time) const {
  return static_cast<uint16_t>(std::lround(position_at(time) * kAdcMax));
}

}  // namespace stepdance::sim
