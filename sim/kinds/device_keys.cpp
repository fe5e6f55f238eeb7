// Readers of keys several device kinds share.
#include "kinds/device_keys.hpp"

#include <string>

namespace stepdance::sim {

using scenario::IntegerRange;
using scenario::NumberRange;
using scenario::TableReader;

DeviceKey number_key(const char* name, const NumberRange& range) {
  return DeviceKey{name, DeviceKey::Type::kNumber, range.low, range.high, range.unit};
}

DeviceKey integer_key(const char* name, const IntegerRange& range) {
  return DeviceKey{name, DeviceKey::Type::kInteger, static_cast<double>(range.low), static_cast<double>(range.high),
                   range.unit};
}

void read_bounded(TableReader& reader, const char* key, const NumberRange& range, double& out) {
  if (const auto value = reader.number(key, range)) out = *value;
}

void read_pulses_per_revolution(TableReader& reader, int32_t& out) {
  if (const auto pulses = reader.integer("pulses_per_revolution", kPulsesPerRevolution)) {
    out = static_cast<int32_t>(*pulses);
  }
}

NumberRange run_time_range(const scenario::ParseContext& context) {
  const double last_s = context.duration_valid ? to_seconds(context.scenario.duration) : scenario::ranges::kTimeS.high;
  return NumberRange{0, last_s, false, "s"};
}

void read_i2c_address(DeviceReading& reading, int fallback) {
  reading.device.i2c_address = fallback;
  const auto address = reading.reader.integer("address");
  if (!address) return;
  if (*address >= 0x08 && *address <= 0x77) {
    reading.device.i2c_address = static_cast<int>(*address);
  } else {
    reading.reader.error("address",
                         "'address' must be a 7-bit I2C address in 0x08..0x77, got " + std::to_string(*address));
  }
}

}  // namespace stepdance::sim
