// Readers of keys several device kinds share: bounded numbers, pulses per revolution, moments of
// the run and I2C addresses.
#pragma once

#include <cstdint>

#include "kinds/device_kind.hpp"

namespace stepdance::sim {

/// pulses_per_revolution: 1..1,000,000 per channel (counted ×4).
inline constexpr scenario::IntegerRange kPulsesPerRevolution{1, 1000000, "pulses"};
/// bounce_ms of a button or limit switch.
inline constexpr scenario::NumberRange kBounceMs{0, 1000, false, "ms"};

/// The key's description for DeviceKind::keys.
DeviceKey number_key(const char* name, const scenario::NumberRange& range);
DeviceKey integer_key(const char* name, const scenario::IntegerRange& range);

/// A number in its range into `out`; out of range is reported by the reader and `out` kept.
void read_bounded(scenario::TableReader& reader, const char* key, const scenario::NumberRange& range, double& out);
/// pulses_per_revolution into `out` (kept when absent or wrong).
void read_pulses_per_revolution(scenario::TableReader& reader, int32_t& out);
/// A moment of the run in seconds: [0, duration_s] (a day while the duration is unknown).
scenario::NumberRange run_time_range(const scenario::ParseContext& context);
/// address: a 7-bit I2C address in 0x08..0x77 (`fallback` when absent); sets device.i2c_address.
void read_i2c_address(DeviceReading& reading, int fallback);

}  // namespace stepdance::sim
