// waveform.cpp: STEP/DIR stimulus for the servo board, built frame by frame with microsecond timing.
#include "waveform.h"

#include <algorithm>
#include <cstdlib>

namespace servo_sim {

Waveform::Waveform(std::uint64_t start_us) : now_us_(start_us) {}

void Waveform::set_dir(std::uint64_t time_us, bool high) {
  if (high != dir_high_) {
    events_.push_back({time_us, Line::dir, high});
    dir_high_ = high;
  }
}

void Waveform::pulse(std::uint64_t rise_us, std::uint32_t width_us) {
  events_.push_back({rise_us, Line::step, true});
  events_.push_back({rise_us + width_us, Line::step, false});
  rises_.push_back({rise_us, static_cast<std::int8_t>(dir_high_ ? 1 : -1)});
}

void Waveform::stepdance_frames(const std::vector<std::int8_t>& directions, std::uint32_t pulse_us) {
  for (const std::int8_t direction : directions) {
    set_dir(now_us_, direction > 0);
    pulse(now_us_ + kDirLeadUs, pulse_us);
    now_us_ += kFrameUs;
  }
}

void Waveform::stepdance_steps(std::int32_t steps, std::uint32_t pulse_us) {
  const std::int8_t direction = steps >= 0 ? 1 : -1;
  stepdance_frames(std::vector<std::int8_t>(static_cast<std::size_t>(std::abs(steps)), direction), pulse_us);
}

void Waveform::frame_with_dir_flip_mid_pulse(bool dir_high_at_rise, std::uint32_t pulse_us,
                                             std::uint32_t flip_after_us) {
  set_dir(now_us_, dir_high_at_rise);
  const std::uint64_t rise_us = now_us_ + kDirLeadUs;
  pulse(rise_us, pulse_us);
  events_.push_back({rise_us + flip_after_us, Line::dir, !dir_high_at_rise});
  dir_high_ = !dir_high_at_rise;
  std::stable_sort(events_.begin(), events_.end(),
                   [](const PinEvent& a, const PinEvent& b) { return a.time_us < b.time_us; });
  now_us_ += kFrameUs;
}

void Waveform::step_at_us(std::uint64_t rise_us, std::int8_t direction, std::uint32_t pulse_us) {
  set_dir(rise_us - kDirLeadUs, direction > 0);
  pulse(rise_us, pulse_us);
  now_us_ = rise_us + pulse_us;
}

void Waveform::pause_frames(std::uint64_t frames) { now_us_ += frames * kFrameUs; }

std::int32_t Waveform::position_at_us(std::uint64_t time_us) const {
  std::int32_t position_steps = 0;
  for (const Rise& rise : rises_) {
    if (rise.time_us > time_us) {
      break;
    }
    position_steps += rise.direction;
  }
  return position_steps;
}

std::int32_t Waveform::final_position_steps() const { return position_at_us(now_us_); }

}  // namespace servo_sim
