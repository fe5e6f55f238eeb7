// The `$` settings table and its write rules.
#include "stepdance/interfaces/gcode/grbl_settings.hpp"

#include <math.h>

namespace stepdance::gcode {

namespace {
// Grbl keeps its whole-number settings in one byte each (settings.c: `uint8_t int_value`).
constexpr double kLargestByteSetting = 255.0;

// A value the setting can hold: finite, not negative, and for a byte setting at most 255.
bool fits(const GrblSetting& setting, double value) {
  return isfinite(value) && value >= 0.0 && (!setting.integer || value <= kLargestByteSetting);
}
}  // namespace

GrblSettings::GrblSettings()
    : settings_{
          {0, 10, true, true},      {1, 25, true, true},      {2, 0, true, true},       {3, 0, true, true},
          {4, 0, true, true},       {5, 0, true, true},       {6, 0, true, true},       {10, 3, true, true},
          {11, 0.010, false, true}, {12, 0.002, false, true}, {13, 0, true, true},      {20, 0, true, true},
          {21, 0, true, true},      {22, 0, true, true},      {23, 0, true, true},      {24, 25, false, true},
          {25, 500, false, true},   {26, 250, true, true},    {27, 1, false, true},     {30, 1000, true, true},
          {31, 0, true, true},      {32, 0, true, true},      {100, 0, false, false},   {101, 0, false, false},
          {102, 0, false, false},   {110, 5000, false, true}, {111, 5000, false, true}, {112, 1000, false, true},
          {120, 1000, false, true}, {121, 1000, false, true}, {122, 200, false, true},  {130, 300, false, true},
          {131, 220, false, true},  {132, 50, false, true},
      } {
  for (GrblSetting& setting : settings_) setting.default_value = setting.value;
}

// A linear search over ~35 settings: called from the loop only, on `$` commands and at start.
const GrblSetting* GrblSettings::find(uint32_t number) const {
  for (const GrblSetting& setting : settings_) {
    if (setting.number == number) return &setting;
  }
  return nullptr;
}

double GrblSettings::value(uint32_t number) const {
  const GrblSetting* setting = find(number);
  return setting != nullptr ? setting->value : 0.0;
}

// Grbl 1.1h's settings_store_global_setting: a negative value is error:4 before anything else;
// integer settings take the value truncated; $0 (step pulse, µs) below 3 is error:6; $20 (soft
// limits) on without $22 (homing) is error:10, and $22 off turns $20 off. A whole-number setting
// above 255 is error:2 here, where Grbl's byte would wrap (docs/gcode.md, `byte-settings`).
GrblError GrblSettings::write(uint32_t number, double value) {
  if (!isfinite(value)) return GrblError::kBadNumberFormat;
  if (value < 0.0) return GrblError::kNegativeValue;
  GrblSetting* setting = writable_setting(number);
  if (setting == nullptr) return GrblError::kInvalidDollarStatement;
  if (setting->integer) value = trunc(value);
  if (!fits(*setting, value)) return GrblError::kBadNumberFormat;  // above 255: one byte cannot hold it
  if (number == 0 && value < 3.0) return GrblError::kStepPulseTooShort;
  if (number == 20 && value != 0.0 && !homing_enabled()) return GrblError::kSoftLimitNeedsHoming;
  setting->value = value;
  setting->host_set = true;
  if (number == 22 && value == 0.0) {
    GrblSetting* soft_limits = writable_setting(20);
    soft_limits->value = 0.0;
    soft_limits->host_set = true;
  }
  return GrblError::kOk;
}

// Loading from the store is stricter than a host write: a stored value that does not fit its setting
// marks the whole image corrupt (no truncation, no silent repair).
GrblError GrblSettings::load(uint32_t number, double value) {
  GrblSetting* setting = writable_setting(number);
  if (setting == nullptr) return GrblError::kInvalidDollarStatement;
  if (!fits(*setting, value) || (setting->integer && value != trunc(value))) return GrblError::kBadNumberFormat;
  setting->value = value;
  setting->host_set = true;
  return GrblError::kOk;
}

GrblSetting* GrblSettings::writable_setting(uint32_t number) {
  GrblSetting* setting = const_cast<GrblSetting*>(find(number));
  return (setting != nullptr && setting->writable) ? setting : nullptr;
}

// The sketch sets the default; a value the host wrote ($N=v, stored) keeps precedence over it, and
// $RST=$ returns to the sketch's value, not Grbl's.
bool GrblSettings::set_from_sketch(uint32_t number, double value) {
  GrblSetting* setting = const_cast<GrblSetting*>(find(number));
  if (setting == nullptr || !fits(*setting, value)) return false;
  setting->default_value = value;
  if (!setting->host_set) setting->value = value;
  setting->sketch_set = true;
  return true;
}

// Like set_from_sketch (the channels' steps/mm become the default) without marking it as the sketch's
// own choice, so the start-up check can still tell a sketch value from a derived one.
bool GrblSettings::set_from_machine(uint32_t number, double value) {
  const GrblSetting* setting = find(number);
  const bool sketch_set = setting != nullptr && setting->sketch_set;
  if (!set_from_sketch(number, value)) return false;
  const_cast<GrblSetting*>(setting)->sketch_set = sketch_set;
  return true;
}

void GrblSettings::restore_defaults() {
  for (GrblSetting& setting : settings_) {
    setting.value = setting.default_value;
    setting.host_set = false;
  }
}

}  // namespace stepdance::gcode
