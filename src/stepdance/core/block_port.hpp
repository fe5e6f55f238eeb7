// BlockPort: the typed connection point through which blocks exchange positions and changes.
#pragma once

#include <stdint.h>

#include "stepdance/core/units.hpp"

namespace stepdance {

class Block;

/// A connection point attached to one state variable of a block (its *target*, in block units).
///
/// Units: everything written in or read out is in *world* units; the target is in *block* units;
/// world = block × ratio, with ratio = world_units / block_units from set_ratio() (kept in double).
///
/// Each frame a block typically does: `input.pull(); input.update(); compute; output.set(v);
/// output.push();`. Writes between two updates accumulate (INCREMENTAL) or overwrite (ABSOLUTE);
/// update() applies them to the target and records the change it applied.
///
/// Differences from the original library (bugs fixed, documented in docs/api.md):
///  - the ratio is double, not float;
///  - push(INCREMENTAL) and pull(INCREMENTAL) deliver each committed change exactly once, so an
///    idle peer is never re-read and nothing is counted twice;
///  - deep reads are in world units everywhere; deep pushes stop nowhere silently.
///
/// Context: unless a method says otherwise, frame ISR, or loop while the engine is stopped.
class BlockPort {
 public:
  BlockPort();
  /// Leaves the list of attached ports. Context: loop.
  ~BlockPort();
  BlockPort(const BlockPort&) = delete;
  BlockPort& operator=(const BlockPort&) = delete;

  /// Attaches the port to a block's state variable, with a direction and owner for deep sync.
  /// Without begin() the port holds its own private state. Context: loop.
  void begin(DecimalPosition* target, BlockPortDirection direction = BLOCKPORT_UNDEFINED, Block* parent = nullptr);

  /// world_units of the outside world equal block_units of the block. Precondition: both
  /// non-zero (a zero argument leaves the ratio unchanged). Context: any.
  void set_ratio(double world_units, double block_units = 1.0);
  /// World units per block unit. Context: any.
  double ratio() const { return world_per_block_; }

  /// Connects this port to a peer and sets the default mode of push()/pull(). A port has one
  /// peer; mapping again replaces it. GLOBAL behaves as ABSOLUTE here. Context: loop.
  void map(BlockPort* peer, PositionMode mode = INCREMENTAL);
  /// The mapped peer, or nullptr. Context: any.
  BlockPort* peer() const { return peer_; }
  /// The mode push() and pull() use without an argument (set by map()). Context: any.
  PositionMode default_mode() const { return mode_; }

  /// Writes a value in world units: INCREMENTAL adds to this frame's pending change, ABSOLUTE
  /// replaces the pending position. Used by pushers and by user code. Context: any.
  void write(double world_value, PositionMode mode = INCREMENTAL);
  /// Applies pending writes to the target: new = last absolute write + all increments.
  /// Direct writes to the target since the last update are overridden. Context: owner's run().
  void update();
  /// Adopts a target that was changed directly (by an ISR) and records the change. Context: owner.
  void reverse_update();
  /// Sets the target now, in block units, and records the change. Context: owner's run().
  void set(double block_value, PositionMode mode = ABSOLUTE);
  /// Moves the target to value (world units, or block units if raw) without any change
  /// reaching a peer. Context: any (interrupts are held off while it runs).
  void reset(double value, bool raw = false);

  /// Sends this port's committed change (INCREMENTAL) or position (ABSOLUTE) to its peer.
  void push();
  void push(PositionMode mode);
  /// Writes the peer's committed change (INCREMENTAL) or position (ABSOLUTE) into this port.
  /// Call before update().
  void pull();
  void pull(PositionMode mode);

  /// World units. After update(): INCREMENTAL = change applied, ABSOLUTE = position.
  /// With writes pending: INCREMENTAL = pending change, ABSOLUTE = position after the update.
  /// Context: any.
  double read(PositionMode mode) const;
  /// read(ABSOLUTE). Context: any.
  double read_absolute() const { return read(ABSOLUTE); }
  /// The raw target in block units. Context: any.
  double read_target() const { return *target_; }

  /// Deep push (alias reset_deep): sets this port and, through kinematics and channels,
  /// everything downstream to the position `world_value` without producing motion.
  void push_deep(double world_value);
  void reset_deep(double world_value) { push_deep(world_value); }
  /// Deep pull: adopts the downstream machine position into this port; returns it (world).
  double pull_deep();
  /// Deep read: the downstream machine position seen from this port (world), changing nothing.
  double read_deep();

  /// Gate push() and pull() on or off. A change committed or offered while gated is dropped,
  /// never delivered after enable() (as in the original). Context: any.
  void enable() { enabled_ = true; }
  void disable() { enabled_ = false; }
  /// True unless disable() gated the port. Context: any.
  bool is_enabled() const { return enabled_; }

  /// Unit conversions with this port's ratio. Context: any.
  double convert_block_to_world_units(double block_value) const { return block_value * world_per_block_; }
  double convert_world_to_block_units(double world_value) const { return world_value * block_per_world_; }

  /// Sum of every change committed by update/set/reverse_update since begin, in world units.
  /// Context: any.
  double committed_total() const { return committed_world_; }
  /// The port's direction in deep chains. Context: any.
  BlockPortDirection direction() const { return direction_; }
  /// The block the port was begun with, or nullptr. Context: any.
  Block* parent() const { return parent_; }

  /// Every port begun with a parent block, as an intrusive list (no heap): the engine derives
  /// the block order from it. Context: loop.
  static BlockPort* first_attached() { return first_attached_; }
  BlockPort* next_attached() const { return next_attached_; }

  /// Public so sketches that wrote into it directly (physical_ui_module) still compile.
  DecimalPosition incremental_buffer = 0;
  DecimalPosition absolute_buffer = 0;

 private:
  void commit(double block_change);
  void attach();
  void detach();

  static BlockPort* first_attached_;

  DecimalPosition own_state_ = 0;
  DecimalPosition* target_;
  double world_per_block_ = 1.0;
  double block_per_world_ = 1.0;  // the inverse, so the frame path multiplies instead of dividing
  double committed_world_ = 0;
  double pushed_total_ = 0;  // committed_world_ at the last incremental push
  double pulled_total_ = 0;  // peer's committed_total() at the last incremental pull
  BlockPort* peer_ = nullptr;
  Block* parent_ = nullptr;
  BlockPort* next_attached_ = nullptr;
  bool attached_ = false;
  PositionMode mode_ = INCREMENTAL;
  BlockPortDirection direction_ = BLOCKPORT_UNDEFINED;
  bool update_has_run_ = true;
  bool enabled_ = true;
};

}  // namespace stepdance
