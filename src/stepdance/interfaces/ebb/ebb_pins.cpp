// EbbPins: the EBB's driver, microstep and pen pins from the emulated state; other pins latched.
#include "stepdance/interfaces/ebb/ebb_pins.hpp"

namespace stepdance::ebb {
namespace {

constexpr int kPortA = 0, kPortB = 1, kPortC = 2, kPortE = 4;

/// MS1, MS2, MS3 for microstep modes 1 (1/16) … 5 (full step), as bits 0, 1, 2.
constexpr uint8_t kMicrostepPins[6] = {0, 0b111, 0b011, 0b010, 0b001, 0b000};

uint8_t microstep_pin(const EbbDriverState& driver, int bit) {
  const uint8_t mode = driver.microstep_mode <= 5 ? driver.microstep_mode : 1;
  return static_cast<uint8_t>((kMicrostepPins[mode] >> bit) & 1);
}

}  // namespace

void EbbPins::set_direction(int port, int pin, bool input) {
  const uint8_t bit = static_cast<uint8_t>(1u << pin);
  input_[port] = static_cast<uint8_t>(input ? input_[port] | bit : input_[port] & ~bit);
}

void EbbPins::set_output(int port, int pin, bool high) {
  const uint8_t bit = static_cast<uint8_t>(1u << pin);
  latch_[port] = static_cast<uint8_t>(high ? latch_[port] | bit : latch_[port] & ~bit);
}

// PI on a pin the EBB wires to its drivers or pen reads the emulated state (clients read MS1–MS3 and
// the enables to learn the microstep mode); other pins read their latch when outputs, 0 as inputs.
uint8_t EbbPins::read(int port, int pin, const EbbDriverState& driver) const {
  uint8_t level = 0;
  if (driver_pin(port, pin, driver, level)) return level;
  const bool output = ((input_[port] >> pin) & 1) == 0;
  return output ? static_cast<uint8_t>((latch_[port] >> pin) & 1) : 0;
}

// The EBB's wiring: RE0 motor 1 enable and RC1 motor 2 enable (active low), RE2/RE1/RA6 MS1/MS2/MS3,
// RB4 pen (low = up in this emulation), RB1 the servo output (read low).
bool EbbPins::driver_pin(int port, int pin, const EbbDriverState& driver, uint8_t& level) const {
  if (port == kPortE && pin == 0)
    level = driver.motor_enabled[0] ? 0 : 1;
  else if (port == kPortC && pin == 1)
    level = driver.motor_enabled[1] ? 0 : 1;
  else if (port == kPortE && pin == 2)
    level = microstep_pin(driver, 0);
  else if (port == kPortE && pin == 1)
    level = microstep_pin(driver, 1);
  else if (port == kPortA && pin == 6)
    level = microstep_pin(driver, 2);
  else if (port == kPortB && pin == 4)
    level = driver.pen_up ? 0 : 1;
  else if (port == kPortB && pin == 1)
    level = 0;
  else
    return false;
  return true;
}

}  // namespace stepdance::ebb
