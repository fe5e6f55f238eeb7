// The engine's frame period: 40 µs by default, shorter when a sketch chooses a faster stream.
#pragma once

#include <stdint.h>

#include "stepdance/core/status.hpp"

namespace stepdance {

/// The frame period every sketch gets unless it chooses another one (25 kHz).
constexpr uint32_t kDefaultFramePeriodUs = 40;
/// The shortest and longest frame periods the engine runs, in microseconds.
constexpr uint32_t kShortestFramePeriodUs = 10;
constexpr uint32_t kLongestFramePeriodUs = 40;
/// The 1 kHz context's period in microseconds; every supported frame period divides it.
constexpr uint32_t kKilohertzPeriodUs = 1000;

/// True for the periods the engine runs: whole microseconds from 10 to 40 that divide 1 ms, so
/// the kilohertz tick is a whole number of frames and the frame rate a whole number of hertz:
/// 10, 20, 25 and 40 µs. From 10 µs on, every signal (E's 7 µs pulse with its DIR margins)
/// fits a frame on its own, so no signal is ever stuck. Context: any.
constexpr bool frame_period_supported(uint32_t period_us) {
  return period_us >= kShortestFramePeriodUs && period_us <= kLongestFramePeriodUs &&
         kKilohertzPeriodUs % period_us == 0;
}

/// The chosen period and the rates derived from it, kept together. Frame code reads them every
/// frame (rate limits, time steps), so the readers below are inline loads, not calls.
struct FramePeriod {
  uint32_t period_us = kDefaultFramePeriodUs;
  uint32_t rate_hz = 1000000u / kDefaultFramePeriodUs;
  double period_s = kDefaultFramePeriodUs / 1e6;
  uint32_t frames_per_khz_tick = kKilohertzPeriodUs / kDefaultFramePeriodUs;
};
namespace detail {
/// Written only by set_frame_period_us(), while the engine is stopped; read everywhere.
extern FramePeriod chosen_frame_period;
}  // namespace detail

/// The chosen frame period in microseconds. Context: any.
inline uint32_t frame_period_us() { return detail::chosen_frame_period.period_us; }
/// Frames per second (1 000 000 / frame_period_us()). Context: any.
inline uint32_t frame_rate_hz() { return detail::chosen_frame_period.rate_hz; }
/// The frame period in seconds. Context: any.
inline double frame_period_s() { return detail::chosen_frame_period.period_s; }
/// Frames per kilohertz tick (1000 / frame_period_us()). Context: any.
inline uint32_t frames_per_kilohertz_tick() { return detail::chosen_frame_period.frames_per_khz_tick; }

/// Chooses the frame period. Call in setup() before any begin() (output ports check their
/// format against it) and before dance_start(). An unsupported period, or a call while the engine
/// runs, is refused through the fault path (kBadConfiguration), so dance_start() then refuses
/// too, and the period stays as it was. Returns kOk, kBadArgument or kBusy. Context: loop.
Status set_frame_period_us(uint32_t period_us);

}  // namespace stepdance
