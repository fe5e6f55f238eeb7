// ThresholdGenerator: passes a value on, clamps it, and calls back when it crosses a limit.
#pragma once

#include "stepdance/core/block.hpp"
#include "stepdance/core/block_port.hpp"
#include "stepdance/core/status.hpp"
#include "stepdance/core/units.hpp"

namespace stepdance {

/// Sets `output` to `input`'s position every frame, optionally clamped to upper/lower limits.
/// When the input crosses a limit (from inside to at-or-beyond) its callback runs — once per
/// crossing, in the loop, never in the frame (the original called it from the frame, every
/// frame while beyond). Context: run() in the frame; setters and callbacks in the loop.
class ThresholdGenerator : public Block {
 public:
  /// The class name, for reports. Context: any.
  const char* type_name() const override { return "ThresholdGenerator"; }
  using Callback = void (*)();

  Status begin();
  void setUpperThreshold(double value, bool clamp = false);
  void setLowerThreshold(double value, bool clamp = false);
  void clearUpperThreshold() { has_upper_ = false; }
  void clearLowerThreshold() { has_lower_ = false; }
  void setUpperCallback(Callback callback) { upper_callback_ = callback; }
  void setLowerCallback(Callback callback) { lower_callback_ = callback; }
  void debugPrint() {}
  /// Crossings seen so far (each ran its callback, if any). Context: any.
  uint32_t upper_crossings() const { return upper_crossings_; }
  uint32_t lower_crossings() const { return lower_crossings_; }

  void run() override;
  void loop() override;

  BlockPort input;
  BlockPort output;

 private:
  volatile double upper_ = 0.0;
  volatile double lower_ = 0.0;
  volatile bool has_upper_ = false;
  volatile bool has_lower_ = false;
  volatile bool clamp_upper_ = false;
  volatile bool clamp_lower_ = false;
  bool was_above_ = false;  // frame only
  bool was_below_ = false;  // frame only
  volatile uint32_t upper_crossings_ = 0;
  volatile uint32_t lower_crossings_ = 0;
  uint32_t upper_called_ = 0;  // loop only
  uint32_t lower_called_ = 0;  // loop only
  Callback upper_callback_ = nullptr;
  Callback lower_callback_ = nullptr;
  DecimalPosition input_state_ = 0;
  DecimalPosition output_state_ = 0;
};

}  // namespace stepdance
