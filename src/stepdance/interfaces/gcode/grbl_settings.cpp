// The `$` settings table and its write rules.
#include "stepdance/interfaces/gcode/grbl_settings.hpp"

#include <math.h>

namespace stepdance::gcode {

GrblSettings::GrblSettings()
    : settings_{
          {0, 10, true, true},      {1, 25, true, true},     {2, 0, true, true},
          {3, 0, true, true},       {4, 0, true, true},      {5, 0, true, true},
          {6, 0, true, true},       {10, 3, true, true},     {11, 0.010, false, true},
          {12, 0.002, false, true}, {13, 0, true, true},     {20, 0, true, true},
          {21, 0, true, true},      {22, 0, true, false},    {23, 0, true, true},
          {24, 25, false, true},    {25, 500, false, true},  {26, 250, true, true},
          {27, 1, false, true},     {30, 1000, true, true},  {31, 0, true, true},
          {32, 0, true, true},      {100, 0, false, false},  {101, 0, false, false},
          {102, 0, false, false},   {110, 5000, false, true}, {111, 5000, false, true},
          {112, 1000, false, true}, {120, 1000, false, true}, {121, 1000, false, true},
          {122, 200, false, true},  {130, 300, false, true}, {131, 220, false, true},
          {132, 50, false, true},
      } {
  for (GrblSetting& setting : settings_) setting.default_value = setting.value;
}

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

GrblError GrblSettings::write(uint32_t number, double value) {
  GrblSetting* setting = const_cast<GrblSetting*>(find(number));
  if (setting == nullptr || !setting->writable) return GrblError::kInvalidDollarStatement;
  if (!isfinite(value)) return GrblError::kBadNumberFormat;
  if (value < 0.0) return GrblError::kNegativeValue;
  if (setting->integer && value != floor(value)) return GrblError::kCommandNeedsInteger;
  setting->value = value;
  setting->host_set = true;
  return GrblError::kOk;
}

bool GrblSettings::set_from_sketch(uint32_t number, double value) {
  GrblSetting* setting = const_cast<GrblSetting*>(find(number));
  if (setting == nullptr) return false;
  setting->default_value = value;
  if (!setting->host_set) setting->value = value;
  return true;
}

void GrblSettings::restore_defaults() {
  for (GrblSetting& setting : settings_) {
    setting.value = setting.default_value;
    setting.host_set = false;
  }
}

}  // namespace stepdance::gcode
