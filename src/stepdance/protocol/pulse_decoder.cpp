// Pulse decoder: width in capture ticks → rounded microseconds → signal, or a counted rejection.
#include "stepdance/protocol/pulse_decoder.hpp"

namespace stepdance::protocol {

uint8_t rounded_width_us(const CapturedPulse& pulse, const CaptureClock& clock) {
  const uint32_t ticks = (pulse.fall_ticks - pulse.rise_ticks) & clock.counter_mask;
  const uint32_t whole_us = ticks / clock.ticks_per_us;
  const uint32_t remainder = ticks % clock.ticks_per_us;
  const uint32_t rounded = whole_us + (2 * remainder > clock.ticks_per_us ? 1u : 0u);
  return static_cast<uint8_t>(rounded > 255 ? 255 : rounded);
}

DecodedPulse decode_pulse(const CapturedPulse& pulse, const CaptureClock& clock, InputMode mode,
                          uint8_t step_dir_signal) {
  DecodedPulse decoded;
  decoded.width_us = rounded_width_us(pulse, clock);
  decoded.direction = pulse.dir_high ? int8_t{1} : int8_t{-1};
  if (mode == INPUT_MODE_STEP_DIR) {
    if (decoded.width_us < kStepDirMinWidthUs) return decoded;  // kTooShort
    decoded.verdict = PulseVerdict::kAccepted;
    decoded.signal = step_dir_signal < kNumSignals ? step_dir_signal : uint8_t{SIGNAL_X};
    return decoded;
  }
  if (decoded.width_us < kMinPulseWidthUs) return decoded;  // kTooShort
  if (decoded.width_us > kMaxPulseWidthUs) {
    decoded.verdict = PulseVerdict::kTooLong;
    return decoded;
  }
  decoded.verdict = PulseVerdict::kAccepted;
  decoded.signal = static_cast<uint8_t>(decoded.width_us - kMinPulseWidthUs);
  return decoded;
}

}  // namespace stepdance::protocol
