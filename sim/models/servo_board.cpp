// ServoBoard: step counting and once-per-period width sampling, with servo_pulse.h arithmetic.
#include "models/servo_board.hpp"

#include <cstddef>

namespace stepdance::sim {

namespace {
/// Firmware defaults (servo/firmware/servo_settings.h).
constexpr uint16_t kPeriodUs = 24000;
constexpr int16_t kPeriodOffsetUs = 850;
constexpr int16_t kWidthOffsetUs = 40;
constexpr uint16_t kMidpointWidthUs = 1500;
constexpr int32_t kLimit90degSteps = 500;
constexpr int32_t kLimit180degSteps = 750;
}  // namespace

servo_pulse_settings servo_build_settings(ServoBuild build) {
  const int32_t limit = build == ServoBuild::k180deg ? kLimit180degSteps : kLimit90degSteps;
  servo_pulse_settings settings{};
  settings.period_us = kPeriodUs;
  settings.period_offset_us = kPeriodOffsetUs;
  settings.width_offset_us = kWidthOffsetUs;
  settings.midpoint_width_us = kMidpointWidthUs;
  settings.top_limit_steps = limit;
  settings.bottom_limit_steps = -limit;
  return settings;
}

ServoBoard::ServoBoard(ServoBuild build, SimTime power_up)
    : ServoBoard(servo_build_settings(build), power_up, kDefaultSampleDelay) {}

ServoBoard::ServoBoard(const servo_pulse_settings& settings, SimTime power_up, SimTime sample_delay)
    : settings_(settings),
      power_up_(power_up),
      sample_delay_(sample_delay),
      period_(SimTime{servo_pulse_period_us(&settings_)} * kMicrosecond) {}

bool ServoBoard::settings_valid() const {
  return servo_pulse_settings_valid(&settings_) && sample_delay_ >= 0 && sample_delay_ < period_;
}

void ServoBoard::on_step_rising(SimTime time, bool dir_high) {
  if (time < power_up_) {
    ++steps_before_power_up_;
    return;
  }
  advance_to(time);
  position_steps_ += dir_high ? 1 : -1;
}

void ServoBoard::advance_to(SimTime time) {
  if (period_ <= 0) return;
  while (sample_time(next_sample_) <= time) {
    sampled_widths_.push_back(servo_pulse_width_us(&settings_, position_steps_));
    ++next_sample_;
  }
}

int64_t ServoBoard::pulse_index_at(SimTime time) const {
  if (time < power_up_ || period_ <= 0) return -1;
  return (time - power_up_) / period_;
}

uint16_t ServoBoard::neutral_width_us() const { return servo_pulse_width_us(&settings_, 0); }

uint16_t ServoBoard::pulse_width_us_at(SimTime time) {
  advance_to(time);
  const int64_t index = pulse_index_at(time);
  if (index < 0) return 0;
  if (index < 2) return neutral_width_us();
  const auto slot = static_cast<size_t>(index - 2);
  if (slot < sampled_widths_.size()) return sampled_widths_[slot];
  // Only reachable with a sample delay of a period or more (settings_valid() is false).
  return sampled_widths_.empty() ? neutral_width_us() : sampled_widths_.back();
}

bool ServoBoard::output_high_at(SimTime time) {
  const uint16_t width_us = pulse_width_us_at(time);
  const int64_t index = pulse_index_at(time);
  if (index < 0) return false;
  return time - pulse_start(index) < SimTime{width_us} * kMicrosecond;
}

}  // namespace stepdance::sim
