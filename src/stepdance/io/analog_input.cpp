// AnalogInput: raw count → floor/ceiling/deadband map → mapped parameter and loop callback.
#include "stepdance/io/analog_input.hpp"

#include "stepdance/hal/hal.hpp"

namespace stepdance {
namespace {

// The straight line through (x0, y0) and (x1, y1) at x; a vertical line steps from y0 to y1.
double line(double x, double x0, double y0, double x1, double y1) {
  if (x1 == x0) return x < x0 ? y0 : y1;
  return y0 + (x - x0) * (y1 - y0) / (x1 - x0);
}

// Clamps to the closed range between a and b in either order: a floor above the ceiling is how a
// sketch maps a rising knob onto a falling value, so the bounds may arrive reversed.
double clamp_between(double value, double a, double b) {
  const double low = a < b ? a : b;
  const double high = a < b ? b : a;
  if (value < low) return low;
  if (value > high) return high;
  return value;
}

}  // namespace

// Two stages on purpose: the kilohertz tick writes the mapped value (cheap, keeps a mapped
// parameter fresh for the frame), while the user callback runs only in loop context, once per
// new conversion, so a slow callback never delays the engine.
Status AnalogInput::begin(uint8_t pin) {
  const Status started = hal::adc_begin(pin);
  if (started != Status::kOk) return started;
  pin_ = pin;
  samples_seen_ = hal::adc_sample_count(pin);
  const Status tick = register_in(Stage::kKilohertz);
  if (tick != Status::kOk) return tick;
  return register_in(Stage::kLoop);
}

// A mapping is either a float ControlParameter or a double DecimalPosition, never both; the
// kilohertz tick reads the pointers, hence the critical section around the swap.
void AnalogInput::map(ControlParameter* target) {
  hal::CriticalSection guard;
  float_target_ = target;
  double_target_ = nullptr;
}

void AnalogInput::map(DecimalPosition* target) {
  hal::CriticalSection guard;
  double_target_ = target;
  float_target_ = nullptr;
}

// Floor and ceiling are calibration points (raw ADC count → output value), not limits on the
// count: raw values outside them extrapolate and are clamped later in value_at().
void AnalogInput::set_floor(double output_value, uint16_t adc_value) {
  {
    hal::CriticalSection guard;
    floor_value_ = output_value;
    adc_low_ = adc_value;
  }
  refresh_calibration_fields();
}

void AnalogInput::set_ceiling(double output_value, uint16_t adc_value) {
  {
    hal::CriticalSection guard;
    ceiling_value_ = output_value;
    adc_high_ = adc_value;
  }
  refresh_calibration_fields();
}

// Keeps the public slope/intercept fields (part of the original interface, read by sketches) in
// step with the double-precision map that mapped() actually evaluates. The deadband bounds are
// clamped to the 10-bit ADC range 0…1023.
void AnalogInput::refresh_calibration_fields() {
  // The two straight pieces mapped() uses, as slope·raw + intercept.
  auto piece = [](double x0, double y0, double x1, double y1, float& slope, float& intercept) {
    const double m = x1 != x0 ? (y1 - y0) / (x1 - x0) : 0.0;
    slope = static_cast<float>(m);
    intercept = static_cast<float>(y0 - m * x0);
  };
  if (!deadband_enabled_) {
    piece(adc_low_, floor_value_, adc_high_, ceiling_value_, conversion_slope_1, conversion_intercept_1);
    conversion_slope_2 = conversion_slope_1;
    conversion_intercept_2 = conversion_intercept_1;
    adc_deadband_lower = adc_deadband_upper = 0;
    return;
  }
  const double band_low = deadband_centre_ - deadband_half_width_;
  const double band_high = deadband_centre_ + deadband_half_width_;
  piece(adc_low_, floor_value_, band_low, deadband_value_, conversion_slope_1, conversion_intercept_1);
  piece(band_high, deadband_value_, adc_high_, ceiling_value_, conversion_slope_2, conversion_intercept_2);
  adc_deadband_lower = static_cast<uint16_t>(band_low < 0 ? 0 : band_low);
  adc_deadband_upper = static_cast<uint16_t>(band_high > 1023 ? 1023 : band_high);
}

// width is the whole band in ADC counts; a width of 1 is widened to 2 so the band has at least
// one count on each side of the centre.
void AnalogInput::set_deadband(double output_value, uint16_t centre, uint16_t width) {
  hal::CriticalSection guard;
  deadband_value_ = output_value;
  deadband_centre_ = centre;
  deadband_half_width_ = (width == 1 ? 2 : width) / 2.0;
  centre_pending_ = false;
  deadband_enabled_ = true;
  refresh_calibration_fields();
}

// "Here" means the knob's current position. Called from setup() before the ADC has converted,
// there is no reading yet, so the band is disabled and centred on the first conversion instead
// (capture_pending_centre) rather than on a meaningless 0.
void AnalogInput::set_deadband_here(double output_value, uint16_t width) {
  const bool converted = pin_ != 255 && hal::adc_sample_count(pin_) != 0;
  if (converted) {
    set_deadband(output_value, read_raw(), width);
    return;
  }
  set_deadband(output_value, 0, width);
  hal::CriticalSection guard;
  deadband_enabled_ = false;  // until the first conversion gives the centre
  centre_pending_ = true;
}

// Runs in both the kilohertz tick and loop context; whichever sees the first conversion takes
// the centre. The flags change together under the critical section so the tick never maps with
// a half-set band.
void AnalogInput::capture_pending_centre() {
  if (!centre_pending_ || hal::adc_sample_count(pin_) == 0) return;
  {
    hal::CriticalSection guard;
    deadband_centre_ = read_raw();
    centre_pending_ = false;
    deadband_enabled_ = true;
  }
  refresh_calibration_fields();
}

uint16_t AnalogInput::read_raw() const { return pin_ == 255 ? 0 : hal::adc_read(pin_); }

// Piecewise linear: floor → band edge, flat inside the band, band edge → ceiling. Without a
// deadband it is one line through the two calibration points. Not clamped here.
double AnalogInput::mapped(double raw) const {
  if (!deadband_enabled_) return line(raw, adc_low_, floor_value_, adc_high_, ceiling_value_);
  const double band_low = deadband_centre_ - deadband_half_width_;
  const double band_high = deadband_centre_ + deadband_half_width_;
  if (raw < band_low) return line(raw, adc_low_, floor_value_, band_low, deadband_value_);
  if (raw > band_high) return line(raw, band_high, deadband_value_, adc_high_, ceiling_value_);
  return deadband_value_;
}

// Inversion is applied after clamping, so an inverted input spans −ceiling…−floor.
double AnalogInput::value_at(uint16_t raw) const {
  const double value = clamp_between(mapped(raw), floor_value_, ceiling_value_);
  return inverted_ ? -value : value;
}

// Kilohertz-tick context: reads the latest conversion, publishes it in last_value_raw and
// writes the mapped target. pin_ == 255 means begin() never succeeded.
void AnalogInput::write_mapped_parameter() {
  if (pin_ == 255) return;
  capture_pending_centre();
  const uint16_t raw = hal::adc_read(pin_);
  last_value_raw = raw;
  const double value = value_at(raw);
  if (float_target_ != nullptr) *float_target_ = static_cast<float>(value);
  if (double_target_ != nullptr) *double_target_ = value;
}

// Loop context: calls the user callback once per batch of new conversions, compared by the HAL's
// sample counter, so a loop slower than the ADC coalesces several conversions into one call.
void AnalogInput::notify_new_conversions() {
  if (pin_ == 255) return;
  capture_pending_centre();
  const uint32_t samples = hal::adc_sample_count(pin_);
  if (samples == samples_seen_) return;
  samples_seen_ = samples;
  if (callback_ != nullptr) callback_();
}

}  // namespace stepdance
