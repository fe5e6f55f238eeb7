// Homing: the loop-side sequencer of the axes' routines.
#include "stepdance/homing/homing.hpp"

#include "stepdance/core/fault.hpp"

namespace stepdance {

// An axis added after begin() starts at once; before it, begin() starts them all. Five axes at most,
// a fixed array: no heap on the firmware.
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

// Restarting aborts a running routine first, so sources held by it are released before being held
// again. Axes home one after the other, in the order added (the sketch puts Z first if it must
// clear the work), or all at once after set_home_together(true).
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
// Other inputs (an encoder knob, a player) would fight the homing axis for the same target, so they are
// disabled for the routine and re-enabled exactly as found: only ports that were enabled are held.
// If the fixed list is full the port is left enabled and counted (ports_not_held_), not lost.
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

// Loop context. Aborting releases the held sources; the machine keeps its unhomed positions.
void Homing::abort() {
  for (size_t i = 0; i < axis_count_; ++i) axes_[i].abort();
  release_sources();
  running_ = false;
}

// While homing, a homing axis's switch closing is expected, so SafetyInputs asks here before raising a
// limit alarm on it.
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

// Loop context. A fatal fault anywhere (an emergency stop, say) fails the routine too: the frame has
// stopped, so no axis can finish.
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
// The trip point is where the switch first closed on the slow approach, not where the axis stopped
// after the final pull-off; the axis is set to value_at_limit plus the pull-off it has travelled since.
// reset_deep() redefines the position down the whole chain (channel included) without motion.
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
