// The chosen frame period and the rates derived from it, kept together.
#include "stepdance/core/frame_period.hpp"

#include "stepdance/core/engine.hpp"
#include "stepdance/core/fault.hpp"

namespace stepdance {

FramePeriod detail::chosen_frame_period;

// Only periods that divide 1 ms evenly (10, 20, 25, 40 µs) are accepted, so the kilohertz tick is a whole
// number of frames and the rates derived here are exact. Before dance_start() only: blocks check the
// period once, at start (accept_frame_period).
Status set_frame_period_us(uint32_t period_us) {
  if (engine().running()) {
    fault(FaultReason::kBadConfiguration, "set_frame_period_us: the engine is running (call it before dance_start)");
    return Status::kBusy;
  }
  if (!frame_period_supported(period_us)) {
    fault(FaultReason::kBadConfiguration, "set_frame_period_us: unsupported period (10, 20, 25 or 40 us)");
    return Status::kBadArgument;
  }
  FramePeriod& chosen = detail::chosen_frame_period;
  chosen.period_us = period_us;
  chosen.rate_hz = 1000000u / period_us;
  chosen.period_s = period_us / 1e6;
  chosen.frames_per_khz_tick = kKilohertzPeriodUs / period_us;
  return Status::kOk;
}

}  // namespace stepdance
