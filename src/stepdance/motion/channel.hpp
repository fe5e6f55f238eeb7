// Channel: turns a target position (in steps) into at most one step pulse per frame on a signal.
#pragma once

#include <stdint.h>

#include "stepdance/core/block.hpp"
#include "stepdance/core/block_port.hpp"
#include "stepdance/core/status.hpp"
#include "stepdance/core/units.hpp"

namespace stepdance {

class OutputPort;

/// One motor axis (or one parameter carried as steps). Every frame the channel compares the
/// position it should be at with the steps it has taken, and emits one pulse toward the target
/// when the error exceeds half a step and the rate limiter and soft limits allow it.
///
///   input_target_position   ─┐
///                            ├─► (+) ─► [EMA] ─► dead band ±0.5 ─► rate ─► limits ─► pulse
///   input_target_position_2 ─┘
///
/// Units: the state fields are in steps (channel units); the input ports and the limit setters
/// take world units, converted by set_ratio(). All pulses go to one signal of one OutputPort.
///
/// Differences from the original library (bugs fixed):
///  - the rate limiter keeps its remainder, so N pulses/s gives exactly N pulses per second;
///  - soft limits are inclusive and never lose a step: current_position stops at the limit;
///  - a channel begun without a port still runs (it steps its position and counts pulses);
///  - read_deep() of its inputs is in world units, like pull_deep().
class Channel : public Block {
 public:
  /// The class name, for reports. Context: any.
  const char* type_name() const override { return "Channel"; }
  /// Highest pulse rate: one pulse per frame of the chosen period. Context: any.
  static double max_pulse_rate_per_s() { return frame_rate_hz(); }
  /// Refuses (fault path) a period at which its output port cannot carry its signal, e.g. E on
  /// a port begun with OUTPUT_FRAME_8US. Context: loop (dance_start).
  bool accept_frame_period(uint32_t period_us) override;
  /// Both target inputs drive the motor: one step is the inputs' ratio in world units (mm per
  /// step, set_ratio()); false for any other port. Context: loop.
  bool world_units_per_step(const BlockPort& input, double& world_units) const override;
  /// Default number of samples of the EMA filter (α = 1/n).
  static constexpr uint16_t kDefaultFilterSamples = 20;

  Channel();

  /// Resets the state, the rate (one pulse per frame: 25 000 pulses/s at 40 µs) and the statistics, begins both inputs
  /// and registers the channel in the channel stage. kBadArgument if signal ≥ 6 (nothing begun); kFull if the channel
  /// registry is full (a fault is recorded). Context: loop.
  Status begin(OutputPort* port, uint8_t signal);
  /// As begin(port, signal) without a port: the channel runs but emits nothing. Context: loop.
  Status begin();

  /// Caps the pulse rate, in pulses per second (0 .. the frame rate, 25 000 at 40 µs; resolution
  /// 0.001). Over any frame-rate's worth of consecutive frames (one second) of continuous one-way
  /// demand the channel emits exactly
  /// round(pulses_per_s) pulses when that is an integer. Context: any.
  void set_max_pulse_rate(double pulses_per_s);
  /// world_units of the inputs equal channel_units steps (25.4, 2032 → 80 steps/mm). Also
  /// re-converts the soft limits. Precondition: both non-zero. Context: loop.
  void set_ratio(double world_units, double channel_units = 1.0);

  /// Soft limits in world units, inclusive: the channel never steps above the upper or below
  /// the lower limit, and never loses a step against one. Context: loop.
  void set_upper_limit(double world_position);
  void set_lower_limit(double world_position);
  /// Remove one or both soft limits. Context: any.
  void disable_upper_limit() { upper_enabled_ = false; }
  void disable_lower_limit() { lower_enabled_ = false; }
  void disable_limits();
  /// +1 if the current or the commanded position (filtered_target_position) is above the
  /// upper limit, −1 if below the lower limit, 0 otherwise. Context: any.
  int8_t is_outside_limits() const;

  /// Smooths the summed target with an EMA of α = 1/samples (samples ≥ 1; 0 is taken as 1):
  /// f = (f·(n − 1) + target + target_2) / n. The filter starts from the current commanded
  /// position, so enabling it never causes a jump. Context: any.
  void enable_filtering(uint16_t samples = kDefaultFilterSamples);
  /// Steps toward target + target_2 directly again. Context: any.
  void disable_filtering() { filtering_ = false; }

  /// Flips the DIR level handed to the output port (calling it again changes nothing; the
  /// original toggled), or sets it explicitly. The state fields and statistics keep the
  /// channel's own direction. Context: any.
  void invert_output() { inverted_ = true; }
  void invert_output(bool invert) { inverted_ = invert; }

  /// Publishes its names under "<instance_name>." in `registry`, an RPC, which lists them
  /// (docs/rpc.md): the same as registry->enroll(instance_name, *this). Context: loop (setup).
  template <class Registry>
  void enroll(Registry* registry, const char* instance_name) {
    registry->enroll(instance_name, *this);
  }

  /// Deep sync: makes current_position and filtered_target_position equal target + target_2,
  /// so a reset of the inputs re-zeroes the error without a single step. Called by the inputs'
  /// push_deep(). Context: loop (interrupts are held off while it runs) or frame ISR.
  void push_deep() override;

  /// One frame of the stepping law. Called by the engine in the channel stage. Context: frame ISR.
  void run() override;

  /// Pulses the channel emitted in its own forward / reverse direction since begin (counted
  /// also when it has no port, or when the port's DIR is inverted). Context: any.
  uint32_t pulses_forward() const { return pulses_forward_; }
  uint32_t pulses_reverse() const { return pulses_reverse_; }
  /// Frames in which a pulse was demanded but withheld by a soft limit. Context: any.
  uint32_t pulses_withheld_by_limits() const { return pulses_withheld_; }
  /// The output port and signal given to begin() (nullptr / 255 without a port). Context: any.
  OutputPort* output_port() const { return port_; }
  uint8_t signal() const { return signal_; }

  /// Inputs, in world units; both feed the summed target. INPUT ports with this channel as
  /// parent, so deep pushes land here.
  BlockPort input_target_position;
  BlockPort input_target_position_2;

  /// State, in steps. target_position(_2): what the inputs hold; filtered_target_position: the
  /// position the channel steps toward; current_position: the steps taken (its own direction).
  DecimalPosition target_position = 0;
  DecimalPosition target_position_2 = 0;
  DecimalPosition current_position = 0;
  DecimalPosition filtered_target_position = 0;

 private:
  Status start(OutputPort* port, uint8_t signal);
  void reset_state();
  void update_limit_steps();
  double advance_filter();
  void track_direction(double error_steps);
  int8_t demanded_step(double error_steps);
  bool limit_allows(int8_t step) const;
  uint32_t threshold_for(int8_t step) const;
  void meter_credit(int8_t step);
  void emit(int8_t step);

  OutputPort* port_ = nullptr;
  uint8_t signal_ = 255;
  bool inverted_ = false;
  bool filtering_ = false;
  uint16_t filter_samples_ = kDefaultFilterSamples;
  int8_t direction_ = 1;        // hysteresis direction (+1 / −1)
  int8_t last_pulse_step_ = 0;  // +1 / −1 of the last pulse, 0 before the first
  uint32_t credit_per_frame_ = 0;
  uint32_t credit_ = 0;
  bool upper_enabled_ = false;
  bool lower_enabled_ = false;
  double upper_limit_world_ = 0;
  double lower_limit_world_ = 0;
  double upper_limit_steps_ = 0;
  double lower_limit_steps_ = 0;
  uint32_t pulses_forward_ = 0;
  uint32_t pulses_reverse_ = 0;
  uint32_t pulses_withheld_ = 0;
};

}  // namespace stepdance
