// Pulse decoder: width in capture ticks → rounded microseconds → signal, or a counted rejection.
#include "stepdance/protocol/pulse_decoder.hpp"

namespace stepdance::protocol {

// For a source with 64-bit time (the simulator): a pulse longer than the counter's period keeps its
// whole periods in extra_periods, so it is still measured as too long instead of wrapping short.
CapturedPulse captured_from_ticks(uint64_t rise_ticks, uint64_t fall_ticks, bool dir_high, const CaptureClock& clock) {
  const uint64_t period = uint64_t{clock.counter_mask} + 1;
  const uint64_t width = fall_ticks >= rise_ticks ? fall_ticks - rise_ticks : 0;
  const uint64_t extra = width / period;
  CapturedPulse pulse;
  pulse.rise_ticks = static_cast<uint32_t>(rise_ticks & clock.counter_mask);
  pulse.fall_ticks = static_cast<uint32_t>((rise_ticks + width) & clock.counter_mask);
  pulse.dir_high = dir_high;
  pulse.extra_periods = extra > UINT32_MAX ? UINT32_MAX : static_cast<uint32_t>(extra);
  return pulse;
}

// The masked difference is right across one counter wrap between the edges (a 16-bit counter at
// 150 MHz wraps every 437 µs, far beyond any valid pulse).
uint64_t width_ticks(const CapturedPulse& pulse, const CaptureClock& clock) {
  const uint64_t wrapped = (pulse.fall_ticks - pulse.rise_ticks) & clock.counter_mask;
  return uint64_t{pulse.extra_periods} * (uint64_t{clock.counter_mask} + 1) + wrapped;
}

// Nearest microsecond, ties down, so a pulse stretched by the cable (spec "Signals": impedance can
// stretch them) by less than half a microsecond still decodes as its signal. Saturates at 255.
uint8_t rounded_width_us(const CapturedPulse& pulse, const CaptureClock& clock) {
  const uint64_t ticks = width_ticks(pulse, clock);
  const uint64_t per_us = clock.ticks_per_us > 0 ? clock.ticks_per_us : 1;
  const uint64_t whole_us = ticks / per_us;
  const uint64_t remainder = ticks % per_us;
  const uint64_t rounded = whole_us + (2 * remainder > per_us ? 1u : 0u);
  return static_cast<uint8_t>(rounded > 255 ? 255 : rounded);
}

// Capture-ISR context. Spec "Signals" table: width 2 µs = X, 3 = Y, 4 = R, 5 = θ, 6 = Z, 7 = E;
// shorter is noise, longer is rejected (counted by the caller). DIR high = forward. In step/dir mode
// any pulse from the minimum width up is one step of the configured signal, since step/dir sources
// do not encode the axis in the width.
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
