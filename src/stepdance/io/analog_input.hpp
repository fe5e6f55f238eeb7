// AnalogInput: a potentiometer, pedal or joystick axis scaled into a parameter of another block.
#pragma once

#include <stdint.h>

#include "stepdance/core/block.hpp"
#include "stepdance/core/status.hpp"
#include "stepdance/core/units.hpp"

namespace stepdance {

/// An ADC pin turned into a number. The backend converts in the background (10-bit, 0..1023);
/// this block maps the latest conversion to an output value:
///
///   raw count  0 … adc_low ──────► centre − w/2 ═════ centre + w/2 ──────► adc_high … 1023
///   output     floor (held)  linear     out    (held)     out     linear   ceiling (held)
///
/// Without a deadband the map is the single line from (adc_low, floor) to (adc_high, ceiling).
/// The output always stays between the floor and ceiling values.
///
/// Contexts: the mapped parameter is written from the kilohertz stage (1 kHz); the callback
/// runs from the loop stage (dance_loop()), never in an interrupt.
///
/// Differences from the original:
///  - the output is clamped between the floor and ceiling values whichever is larger, so a
///    falling map (floor > ceiling) works;
///  - the deadband is computed in signed arithmetic, so a band near 0 or 1023 cannot wrap;
///  - none for invert(), on purpose: it NEGATES the clamped output (a 0..10 map becomes
///    0..−10), it does not mirror it within [floor, ceiling], exactly as the original, so
///    existing sketches keep their numbers. For a map symmetric about 0 (a joystick, ±50)
///    both readings agree. To mirror a range, swap the floor and ceiling values instead.
///  - the callback runs from the loop, once per pass that saw new conversions, not inside the
///    ADC interrupt once per conversion;
///  - set_deadband_here() does not wait 20 ms: it uses the latest conversion, or the first one
///    if none has completed yet.
class AnalogInput : public Block {
 public:
  /// The class name, for reports. Context: any.
  const char* type_name() const override { return "AnalogInput"; }
  /// The user callback: no arguments, called from the loop.
  using Callback = void (*)();

  AnalogInput() = default;

  /// Starts background conversions of board pin `pin` (e.g. IO_A1) and registers in the
  /// kilohertz and loop stages. kNoSuchPin if the pin has no ADC. Context: loop.
  Status begin(uint8_t pin);

  /// Writes the output value into a float parameter of another block, every millisecond.
  /// Replaces any earlier map(); nullptr unmaps. Context: loop.
  void map(ControlParameter* target);
  /// Writes the output value into a double position of another block, every millisecond.
  /// Replaces any earlier map(); nullptr unmaps. Context: loop.
  void map(DecimalPosition* target);
  /// Calls callback from dance_loop() once per loop pass in which at least one new conversion
  /// completed (several conversions between two passes give one call: the value is a level,
  /// not an event). nullptr removes it. Context: loop.
  void set_callback(Callback callback) { callback_ = callback; }

  /// Output `output_value` at ADC count `adc_value` (0..1023), the low end of the map.
  /// Defaults: 0 at 0. Context: loop.
  void set_floor(double output_value, uint16_t adc_value = 0);
  /// Output `output_value` at ADC count `adc_value` (0..1023), the high end of the map.
  /// Defaults: 1023 at 1023. Context: loop.
  void set_ceiling(double output_value, uint16_t adc_value = 1023);
  /// Holds the output at `output_value` for raw counts within centre ± width/2 (width 1 is
  /// treated as 2, as in the original). `centre` in ADC counts. Context: loop.
  void set_deadband(double output_value, uint16_t centre, uint16_t width = 4);
  /// set_deadband() centred on the current position of the knob: the latest conversion, or
  /// the first conversion to complete if none has yet. Context: loop.
  void set_deadband_here(double output_value = 0, uint16_t width = 4);
  /// Removes the deadband. Context: loop.
  void clear_deadband() {
    deadband_enabled_ = false;
    refresh_calibration_fields();
  }
  /// Toggles negation of the output (see the class comment: negation, not mirroring).
  /// Context: loop.
  void invert() { inverted_ = !inverted_; }

  /// The output value for the latest conversion. Context: loop (or any, it only reads).
  float read() const { return static_cast<float>(value_at(read_raw())); }
  /// The latest conversion, 0..1023 (0 before begin()). Context: any.
  uint16_t read_raw() const;
  /// The output value a raw count maps to with the current settings. Context: any.
  double value_at(uint16_t raw) const;

  /// Kilohertz work: writes the mapped parameter. Called by the engine. Context: kilohertz ISR.
  void run_kilohertz() override { write_mapped_parameter(); }
  /// Loop work: runs the callback after new conversions. Called by dance_loop(). Context: loop.
  void loop() override { notify_new_conversions(); }

  /// Volts at full scale, kept from the original for sketches that convert readings to volts.
  float full_scale_volts = 3.3f;

  /// The original library's public calibration fields, kept as read-only mirrors of the
  /// settings above (writing them changes nothing): the latest raw conversion; the output line
  /// below the deadband (or the whole line without one) as slope and intercept per ADC count;
  /// the line above it; and the band's raw limits.
  volatile uint16_t last_value_raw = 0;
  float conversion_slope_1 = 1.0f;
  float conversion_intercept_1 = 0.0f;
  float conversion_slope_2 = 1.0f;
  float conversion_intercept_2 = 0.0f;
  uint16_t adc_deadband_lower = 0;
  uint16_t adc_deadband_upper = 0;

 private:
  // Virtuals stay inline (no key function): see Block.
  void write_mapped_parameter();
  void notify_new_conversions();
  double mapped(double raw) const;
  void capture_pending_centre();
  void refresh_calibration_fields();

  ControlParameter* float_target_ = nullptr;
  DecimalPosition* double_target_ = nullptr;
  Callback callback_ = nullptr;
  double floor_value_ = 0;
  double ceiling_value_ = 1023;
  double deadband_value_ = 0;
  double deadband_centre_ = 0;
  double deadband_half_width_ = 2;
  uint32_t samples_seen_ = 0;
  uint16_t adc_low_ = 0;
  uint16_t adc_high_ = 1023;
  uint8_t pin_ = 255;
  volatile bool centre_pending_ = false;
  bool deadband_enabled_ = false;
  bool inverted_ = false;
};

}  // namespace stepdance
