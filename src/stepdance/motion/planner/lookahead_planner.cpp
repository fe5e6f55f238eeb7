// Backward and forward passes over the waiting blocks.
#include "stepdance/motion/planner/lookahead_planner.hpp"

#include <math.h>

#include "stepdance/motion/planner/junction.hpp"

namespace stepdance::planner {
namespace {

double min2(double a, double b) { return a < b ? a : b; }

/// Speed reachable from `from` over `length` at `acceleration` (either direction of time).
// v² = v0² + 2aL: constant acceleration over a distance.
double reachable(double from, double acceleration, double length) {
  return sqrt(from * from + 2.0 * acceleration * length);
}

}  // namespace

// Loop context. A block's entry speed is capped by the corner it makes with the previous motion block
// (both junction bounds, with the lower of the two accelerations) and by both cruise speeds. Only XYZ
// directions make a corner; a dwell or an E-only move breaks the chain (entry 0), as a stop.
Status LookaheadPlanner::add(const PlannedBlock& block) {
  if (count_ == kCapacity) return Status::kFull;
  PlannedBlock& slot = at(count_);
  slot = block;
  const bool motion = block.length > 0.0;
  double direction[3] = {};
  const double xyz =
      sqrt(block.delta[0] * block.delta[0] + block.delta[1] * block.delta[1] + block.delta[2] * block.delta[2]);
  if (motion && xyz > 0.0) {
    for (int i = 0; i < 3; ++i) direction[i] = block.delta[i] / xyz;
  }
  slot.max_entry_speed = 0.0;
  if (motion && last_was_motion_ && xyz > 0.0) {
    const double acceleration = min2(last_acceleration_, block.acceleration);
    const double shorter = min2(last_length_, block.length);
    const double corner = min2(junction_speed(last_direction_, direction, junction_deviation_, acceleration),
                               centripetal_junction_speed(last_direction_, direction, shorter, acceleration));
    slot.max_entry_speed = min2(corner, min2(last_cruise_, block.cruise_speed));
  }
  last_was_motion_ = motion && xyz > 0.0;
  for (int i = 0; i < 3; ++i) last_direction_[i] = direction[i];
  last_cruise_ = block.cruise_speed;
  last_length_ = block.length;
  last_acceleration_ = block.acceleration;
  ++count_;
  replan();
  return Status::kOk;
}

// The classic two passes (as in Grbl's planner): backward, every block must be able to stop by the end
// of what is known; forward, from the exit speed of the block last handed to the frame, no block can
// be entered faster than acceleration allows. O(n) per added block over at most kCapacity blocks.
void LookaheadPlanner::replan() {
  // Backward: the last block stops at its end; each entry is what still allows every later stop.
  double exit = 0.0;
  for (size_t k = count_; k-- > 0;) {
    PlannedBlock& block = at(k);
    stop_limit_[slot(k)] = reachable(exit, block.acceleration, block.length);
    block.exit_speed = exit;
    block.entry_speed = min2(block.max_entry_speed, stop_limit_[slot(k)]);
    exit = block.entry_speed;
  }
  // Forward: from the speed the frame will hand over, accelerate as far as each block allows.
  double entry = min2(committed_exit_speed_, count_ > 0 ? at(0).entry_speed : 0.0);
  for (size_t k = 0; k < count_; ++k) {
    PlannedBlock& block = at(k);
    block.entry_speed = entry;
    block.exit_speed = min2(block.exit_speed, reachable(entry, block.acceleration, block.length));
    block.exit_speed = min2(block.exit_speed, block.cruise_speed);
    entry = block.exit_speed;
  }
}

// The head may go to the frame only when no later block could raise its exit speed: when its limit
// comes from itself or its corner rather than from the need to stop at the end of the queue. flush
// forces it out when the frame would otherwise run dry (it then exits at the stop-safe speed).
bool LookaheadPlanner::take_final(PlannedBlock& out, bool flush) {
  if (count_ == 0) return false;
  PlannedBlock& head = at(0);
  // The head's exit is final when something other than "the queue stops after the next block"
  // limits it: its own acceleration, the corner, or the cruise speeds.
  bool final_speed = false;
  if (count_ > 1) {
    const double own_limit = min2(reachable(head.entry_speed, head.acceleration, head.length), head.cruise_speed);
    const double corner_limit = at(1).max_entry_speed;
    final_speed = min2(own_limit, corner_limit) <= stop_limit_[slot(1)];
  }
  if (!final_speed && !flush) return false;
  out = head;
  committed_exit_speed_ = head.exit_speed;
  head_ = (head_ + 1) % kCapacity;
  --count_;
  return true;
}

void LookaheadPlanner::clear() {
  head_ = 0;
  count_ = 0;
  committed_exit_speed_ = 0.0;
  last_was_motion_ = false;
}

}  // namespace stepdance::planner
