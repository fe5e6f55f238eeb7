// Homing: the loop-side sequencer of the axes' routines.
#include "stepdance/homing/homing.hpp"

#include "stepdance/core/fault.hpp"

namespace stepdance {

Status Homing::add_axis(uint8_t limit_pin, double value_at_limit, float direction, float velocity, BlockPort* target) {
  if (target == nullptr) return Status::kBadArgument;
  if (axis_count_ == kMaxAxes) {
    report_fault(FaultLevel::kWarning, FaultReason::kRegistryFull, "homing", "more than 5 homing axes");
    return Status::kFull;
  }
  HomingAxis& axis = axes_[axis_count_++];
  axis.configure(limit_pin, value_at_limit, direction, velocity, target);
  return begun_ ? axis.begin() : Status::kOk;
}

Status Homing::begin() {
  for (size_t i = 0; i < axis_count_; ++i) {
    const Status status = axes_[i].begin();
    if (status != Status::kOk) return status;
  }
  begun_ = true;
  return register_in(Stage::kLoop);
}

void Homing::start_homing_routine() {
  if (running_) abort();
  homed_ = failed_ = false;
  running_ = axis_count_ > 0;
  current_ = 0;
  for (size_t i = 0; i < axis_count_; ++i) axes_[i].abort();
  for (size_t i = 0; i < axis_count_; ++i) {
    if (together_ || i == 0) start_axis(axes_[i]);
  }
}

void Homing::start_axis(HomingAxis& axis) {
  hold_other_sources(axis);
  axis.start();
}

// Gates every enabled port, other than the axis's own output, that pushes into its target.
void Homing::hold_other_sources(const HomingAxis& axis) {
  for (BlockPort* port = BlockPort::first_attached(); port != nullptr; port = port->next_attached()) {
    if (port->peer() != axis.target() || port == &axis.output || port->direction() == BLOCKPORT_INPUT) continue;
    if (!port->is_enabled() || held_.contains(port)) continue;
    if (held_.push_back(port) != Status::kOk) {
      ++ports_not_held_;
      continue;
    }
    port->disable();
  }
}

void Homing::release_sources() {
  for (BlockPort* port : held_) port->enable();
  held_.clear();
}

void Homing::abort() {
  for (size_t i = 0; i < axis_count_; ++i) axes_[i].abort();
  release_sources();
  running_ = false;
}

bool Homing::owns_switch(uint8_t pin) const {
  if (!running_) return false;
  for (size_t i = 0; i < axis_count_; ++i) {
    if (axes_[i].limit_pin() == pin) return true;
  }
  return false;
}

bool Homing::all_axes(uint8_t state) const {
  for (size_t i = 0; i < axis_count_; ++i) {
    if (axes_[i].state() != state) return false;
  }
  return true;
}

void Homing::loop() {
  if (!running_) return;
  bool any_failed = fault_level() == static_cast<uint8_t>(FaultLevel::kFatal);
  for (size_t i = 0; i < axis_count_; ++i) any_failed = any_failed || axes_[i].state() == HOMING_AXIS_STATE_FAILED;
  if (any_failed) {
    fail();
    return;
  }
  if (!together_ && axes_[current_].state() == HOMING_AXIS_STATE_FINISHED && current_ + 1 < axis_count_) {
    start_axis(axes_[++current_]);
    return;
  }
  if (all_axes(HOMING_AXIS_STATE_FINISHED)) finish();
}

// Every axis has homed: the trip points become value_at_limit through the whole chain.
void Homing::finish() {
  for (size_t i = 0; i < axis_count_; ++i) {
    HomingAxis& axis = axes_[i];
    axis.output.reset_deep(axis.value_at_limit() + (axis.position() - axis.trip_position()));
  }
  release_sources();
  running_ = false;
  homed_ = true;
  if (on_finished_ != nullptr) on_finished_();
}

void Homing::fail() {
  abort();
  failed_ = true;
  if (on_failed_ != nullptr) on_failed_();
}

}  // namespace stepdance
