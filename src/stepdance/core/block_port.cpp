// BlockPort buffer algebra, push/pull and deep synchronisation.
#include "stepdance/core/block_port.hpp"

#include "stepdance/core/block.hpp"
#include "stepdance/hal/hal.hpp"

namespace stepdance {

BlockPort* BlockPort::first_attached_ = nullptr;

BlockPort::BlockPort() : target_(&own_state_) {}

BlockPort::~BlockPort() { detach(); }

// Every port with a parent joins one intrusive list (no heap), so the engine can order blocks by
// their mappings and homing can find every source feeding a target.
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

// The buffers start at the target's current value so the first update() produces no change.
void BlockPort::begin(DecimalPosition* target, BlockPortDirection direction, Block* parent) {
  target_ = target != nullptr ? target : &own_state_;
  direction_ = direction;
  parent_ = parent;
  if (parent != nullptr) attach();
  absolute_buffer = *target_;
  incremental_buffer = 0;
  update_has_run_ = true;
}

// world_units of the outside world per block_units inside the block (e.g. 1 mm per 40 steps); both
// directions are stored so neither conversion divides. A zero is ignored rather than dividing by it.
void BlockPort::set_ratio(double world_units, double block_units) {
  if (world_units == 0.0 || block_units == 0.0) return;
  world_per_block_ = world_units / block_units;
  block_per_world_ = block_units / world_units;
}

// The running totals start equal, so mapping a port to one that has already moved does not deliver
// that past motion as a jump.
void BlockPort::map(BlockPort* peer, PositionMode mode) {
  peer_ = peer;
  mode_ = mode;
  pushed_total_ = committed_world_;
  pulled_total_ = peer != nullptr ? peer->committed_total() : 0.0;
}

// The buffer algebra (original-library.md §3): several writers may write one port within a
// frame; incremental writes add up, an absolute write replaces the base. The first write after an
// update() starts a new frame's sum.
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

// committed_world_ is the running total of every change in world units; pushes and pulls of peers
// deliver differences of it, so nothing is lost or counted twice however often they run.
void BlockPort::commit(double block_change) {
  incremental_buffer = block_change;
  committed_world_ += block_change * world_per_block_;
  update_has_run_ = true;
}

// Frame context, by the owner block: applies this frame's writes to the target.
void BlockPort::update() {
  if (update_has_run_) incremental_buffer = 0;  // nothing written since the last update
  const double position = absolute_buffer + incremental_buffer;
  const double change = position - *target_;
  absolute_buffer = position;
  *target_ = position;
  commit(change);
}

// For a target changed directly (by an ISR, say) rather than through write(): the buffers take the
// target's value and the change is committed for the peers.
void BlockPort::reverse_update() {
  const double position = *target_;
  const double change = position - absolute_buffer;
  absolute_buffer = position;
  commit(change);
}

// Like write() then update() in one step, in block units, for a source block that owns its value.
void BlockPort::set(double block_value, PositionMode mode) {
  const double position = mode == INCREMENTAL ? *target_ + block_value : block_value;
  const double change = position - *target_;
  *target_ = position;
  absolute_buffer = position;
  commit(change);
}

// Moves the port without motion: the target jumps but nothing is committed, so peers see no change.
// raw: value is already in block units.
void BlockPort::reset(double value, bool raw) {
  const double position = raw ? value : value * block_per_world_;
  hal::CriticalSection guard;
  *target_ = position;
  absolute_buffer = position;
  incremental_buffer = 0;
  update_has_run_ = true;
}

void BlockPort::push() { push(mode_); }

// A disabled (gated) port drops its changes instead of storing them, so re-enabling an input does not
// deliver everything that happened while it was off in one jump.
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

// The mirror of push(): the reading side takes the difference of the peer's committed total.
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

// Before update() has run this frame, the read includes the writes pending in the buffers; after it,
// only what was applied. Result in world units.
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

// Asks the chain upstream for its position and resets every port on the way to it, without motion.
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

// Reads the position at the end of the chain (the machine side) without changing anything.
double BlockPort::read_deep() {
  if (direction_ == BLOCKPORT_OUTPUT && peer_ != nullptr) return peer_->read_deep();
  if (direction_ == BLOCKPORT_INPUT && parent_ != nullptr) return parent_->read_deep(*this);
  return read(ABSOLUTE);
}

}  // namespace stepdance
