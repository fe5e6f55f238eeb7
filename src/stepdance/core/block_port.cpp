// BlockPort buffer algebra, push/pull and deep synchronisation.
#include "stepdance/core/block_port.hpp"

#include "stepdance/core/block.hpp"
#include "stepdance/hal/hal.hpp"

namespace stepdance {

BlockPort* BlockPort::first_attached_ = nullptr;

BlockPort::BlockPort() : target_(&own_state_) {}

BlockPort::~BlockPort() { detach(); }

void BlockPort::attach() {
  if (attached_) return;
  next_attached_ = first_attached_;
  first_attached_ = this;
  attached_ = true;
}

void BlockPort::detach() {
  if (!attached_) return;
  for (BlockPort** link = &first_attached_; *link != nullptr; link = &(*link)->next_attached_) {
    if (*link == this) {
      *link = next_attached_;
      break;
    }
  }
  next_attached_ = nullptr;
  attached_ = false;
}

void BlockPort::begin(DecimalPosition* target, BlockPortDirection direction, Block* parent) {
  target_ = target != nullptr ? target : &own_state_;
  direction_ = direction;
  parent_ = parent;
  if (parent != nullptr) attach();
  absolute_buffer = *target_;
  incremental_buffer = 0;
  update_has_run_ = true;
}

void BlockPort::set_ratio(double world_units, double block_units) {
  if (world_units == 0.0 || block_units == 0.0) return;
  world_per_block_ = world_units / block_units;
  block_per_world_ = block_units / world_units;
}

void BlockPort::map(BlockPort* peer, PositionMode mode) {
  peer_ = peer;
  mode_ = mode;
  pushed_total_ = committed_world_;
  pulled_total_ = peer != nullptr ? peer->committed_total() : 0.0;
}

void BlockPort::write(double world_value, PositionMode mode) {
  if (update_has_run_) {
    incremental_buffer = 0;
    update_has_run_ = false;
  }
  const double block_value = world_value * block_per_world_;
  if (mode == INCREMENTAL) {
    incremental_buffer = incremental_buffer + block_value;
  } else {
    absolute_buffer = block_value;
  }
}

void BlockPort::commit(double block_change) {
  incremental_buffer = block_change;
  committed_world_ += block_change * world_per_block_;
  update_has_run_ = true;
}

void BlockPort::update() {
  if (update_has_run_) incremental_buffer = 0;  // nothing written since the last update
  const double position = absolute_buffer + incremental_buffer;
  const double change = position - *target_;
  absolute_buffer = position;
  *target_ = position;
  commit(change);
}

void BlockPort::reverse_update() {
  const double position = *target_;
  const double change = position - absolute_buffer;
  absolute_buffer = position;
  commit(change);
}

void BlockPort::set(double block_value, PositionMode mode) {
  const double position = mode == INCREMENTAL ? *target_ + block_value : block_value;
  const double change = position - *target_;
  *target_ = position;
  absolute_buffer = position;
  commit(change);
}

void BlockPort::reset(double value, bool raw) {
  const double position = raw ? value : value * block_per_world_;
  hal::CriticalSection guard;
  *target_ = position;
  absolute_buffer = position;
  incremental_buffer = 0;
  update_has_run_ = true;
}

void BlockPort::push() { push(mode_); }

void BlockPort::push(PositionMode mode) {
  if (peer_ == nullptr) return;
  if (!enabled_) {
    pushed_total_ = committed_world_;  // a gated change is dropped, not delivered later
    return;
  }
  if (mode == INCREMENTAL) {
    const double change = committed_world_ - pushed_total_;
    pushed_total_ = committed_world_;
    peer_->write(change, INCREMENTAL);
  } else {
    peer_->write(absolute_buffer * world_per_block_, ABSOLUTE);
  }
}

void BlockPort::pull() { pull(mode_); }

void BlockPort::pull(PositionMode mode) {
  if (peer_ == nullptr) return;
  if (!enabled_) {
    pulled_total_ = peer_->committed_total();  // a gated change is dropped, not delivered later
    return;
  }
  if (mode == INCREMENTAL) {
    const double total = peer_->committed_total();
    const double change = total - pulled_total_;
    pulled_total_ = total;
    if (change != 0.0) write(change, INCREMENTAL);
  } else {
    write(peer_->read(ABSOLUTE), ABSOLUTE);
  }
}

double BlockPort::read(PositionMode mode) const {
  if (update_has_run_) {
    return (mode == INCREMENTAL ? incremental_buffer : absolute_buffer) * world_per_block_;
  }
  if (mode == INCREMENTAL) {
    return (incremental_buffer + (absolute_buffer - *target_)) * world_per_block_;
  }
  return (incremental_buffer + absolute_buffer) * world_per_block_;
}

// Deep operations hold interrupts off for the whole chain: a frame running halfway through
// would see some ports reset and others not, and turn the difference into motion.
void BlockPort::push_deep(double world_value) {
  hal::CriticalSection guard;
  reset(world_value);
  if (direction_ == BLOCKPORT_INPUT && parent_ != nullptr) {
    parent_->push_deep();
  } else if (direction_ == BLOCKPORT_OUTPUT && peer_ != nullptr) {
    peer_->push_deep(world_value);
  }
}

double BlockPort::pull_deep() {
  hal::CriticalSection guard;
  if (direction_ == BLOCKPORT_OUTPUT && peer_ != nullptr) {
    const double position = peer_->pull_deep();
    reset(position);
    return position;
  }
  if (direction_ == BLOCKPORT_INPUT && parent_ != nullptr) parent_->pull_deep();
  return read(ABSOLUTE);
}

double BlockPort::read_deep() {
  if (direction_ == BLOCKPORT_OUTPUT && peer_ != nullptr) return peer_->read_deep();
  if (direction_ == BLOCKPORT_INPUT && parent_ != nullptr) return parent_->read_deep(*this);
  return read(ABSOLUTE);
}

}  // namespace stepdance
