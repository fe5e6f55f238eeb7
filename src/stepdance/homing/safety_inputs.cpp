// SafetyInputs: debounced limit, emergency-stop, feed-hold and cycle-start inputs.
#include "stepdance/homing/safety_inputs.hpp"

#include "stepdance/hal/hal.hpp"
#include "stepdance/homing/homing.hpp"
#include "stepdance/motion/time_based_interpolator.hpp"

namespace stepdance {

Status SafetyInputs::add_limit(uint8_t pin, bool normally_closed, FaultLevel level) {
  return add(Role::kLimit, pin, normally_closed, level, nullptr);
}

// Always fatal: the engine stops every output at once (enter_safe_state), whatever the sketch asks.
Status SafetyInputs::add_emergency_stop(uint8_t pin, bool normally_closed) {
  return add(Role::kEmergencyStop, pin, normally_closed, FaultLevel::kFatal, nullptr);
}

// Feed hold and cycle start act on a planner's speed override, like Grbl's `!` and `~` realtime
// commands: motion pauses on its path and resumes where it stopped.
Status SafetyInputs::add_feed_hold(uint8_t pin, TimeBasedInterpolator* planner, bool normally_closed) {
  if (planner == nullptr) return Status::kBadArgument;
  return add(Role::kFeedHold, pin, normally_closed, FaultLevel::kWarning, planner);
}

Status SafetyInputs::add_cycle_start(uint8_t pin, TimeBasedInterpolator* planner, bool normally_closed) {
  if (planner == nullptr) return Status::kBadArgument;
  return add(Role::kCycleStart, pin, normally_closed, FaultLevel::kWarning, planner);
}

Status SafetyInputs::add(Role role, uint8_t pin, bool normally_closed, FaultLevel level,
                         TimeBasedInterpolator* planner) {
  if (count_ == kMaxInputs) {
    report_fault(FaultLevel::kWarning, FaultReason::kRegistryFull, "safety inputs", "more than 8 safety inputs");
    return Status::kFull;
  }
  Input& input = inputs_[count_++];
  input.role = role;
  input.pin = pin;
  input.normally_closed = normally_closed;
  input.level = level;
  input.planner = planner;
  return Status::kOk;
}

void SafetyInputs::set_debounce_ms(uint32_t ms) { debounce_ms_ = ms; }

// Sampled at 1 kHz, so debounce_ms_ is the number of stable samples. Every switch closes to 3.3 V
// over a pull-down (the original's wiring). Active level: high for a normally open switch, low
// for a normally closed loop: the closed loop holds the pin high, and a press or a cut wire lets
// the pull-down take it low, so a broken loop reads as pressed (the header's contract).
Status SafetyInputs::begin() {
  for (size_t i = 0; i < count_; ++i) {
    Input& input = inputs_[i];
    const Status status = hal::gpio_mode(input.pin, hal::PinMode::kInputPulldown);
    if (status != Status::kOk) return status;
    input.debouncer.set_stable_samples(debounce_ms_);
    input.debouncer.restart(false, 0);  // an input active at power-on still reports once
  }
  return register_in(Stage::kKilohertz);
}

bool SafetyInputs::read(const Input& input) const { return hal::gpio_read(input.pin) != input.normally_closed; }

// Kilohertz-ISR context: acts on the debounced rising edge only, once per activation, so a switch held
// closed raises one fault, not one per millisecond.
void SafetyInputs::run_kilohertz() {
  for (size_t i = 0; i < count_; ++i) {
    Input& input = inputs_[i];
    if (input.debouncer.sample(read(input), 0) && input.debouncer.level()) on_activated(input);
  }
}

// A feed hold remembers the override in force before the first hold so a repeated hold cannot save
// 0 and make cycle start resume at zero speed. Cycle start without a hold does nothing.
void SafetyInputs::on_activated(Input& input) {
  switch (input.role) {
    case Role::kLimit:
      if (homing_ != nullptr && homing_->owns_switch(input.pin)) return;
      ++limit_hits_;
      report_fault(input.level, FaultReason::kLimitHit, "limit switch", "a hard limit switch closed");
      break;
    case Role::kEmergencyStop:
      ++emergency_stops_;
      report_fault(FaultLevel::kFatal, FaultReason::kHardware, "emergency stop", "the emergency stop was pressed");
      break;
    case Role::kFeedHold:
      ++feed_holds_;
      if (!holding_) held_override_ = input.planner->speed_overide;
      holding_ = true;
      input.planner->speed_overide = 0.0f;
      break;
    case Role::kCycleStart:
      ++cycle_starts_;
      if (holding_) input.planner->speed_overide = held_override_;
      holding_ = false;
      break;
  }
}

void SafetyInputs::report_counters(CounterSink& sink) const {
  sink.counter("limit_hits", limit_hits_);
  sink.counter("emergency_stops", emergency_stops_);
  sink.counter("feed_holds", feed_holds_);
  sink.counter("cycle_starts", cycle_starts_);
}

}  // namespace stepdance
