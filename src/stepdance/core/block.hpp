// Base class of every engine block (ports, channels, generators, kinematics, interfaces).
#pragma once

#include <stdint.h>

#include "stepdance/core/counters.hpp"
#include "stepdance/core/stage.hpp"
#include "stepdance/core/status.hpp"

namespace stepdance {

class BlockPort;

/// A unit of work the engine runs in one context. Blocks register themselves in begin(); at
/// start the engine orders each stage so that producers run before their consumers (see
/// block_order.hpp), otherwise keeping begin() order. Destroying a block unregisters it.
class Block {
 public:
  Block() = default;
  Block(const Block&) = delete;
  Block& operator=(const Block&) = delete;

  /// Lets the block run. Context: any.
  virtual void enable() { enabled_ = true; }
  /// Stops the block from running (its state is kept). Context: any.
  virtual void disable() { enabled_ = false; }
  /// True while the block runs. Context: any.
  bool is_enabled() const { return enabled_; }
  /// The block's class name, for reports (a cycle in the block graph, statistics). Context: any.
  virtual const char* type_name() const { return "Block"; }
  /// Hands the block's statistics to `sink` as named counters (the simulator's summary and
  /// any other reader get them without knowing the class). Default: none. Context: loop.
  virtual void report_counters(CounterSink& sink) const { (void)sink; }

  /// Deep sync, downstream: re-derive outputs from inputs that were just reset, without motion.
  /// Called by an INPUT BlockPort's push_deep(). Context: loop (or frame ISR for GLOBAL moves).
  virtual void push_deep() {}
  /// Deep sync, upstream: adopt the downstream state into this block's inputs.
  /// Called by an INPUT BlockPort's pull_deep(). Context: as push_deep().
  virtual void pull_deep() {}
  /// Deep read: the value `port` (one of this block's INPUT ports) would hold if its state were
  /// re-derived from downstream, in the port's world units, without changing anything.
  /// Default: the port's own absolute value. Context: any.
  virtual double read_deep(BlockPort& port) { return absolute_value(port); }

  /// The original library's spelling of `registry->enroll(instance_name, block)`: publishes the
  /// block's remotely callable names under "<instance_name>." in a name registry (an RPC). The
  /// registry alone knows which names a class has; a class with names repeats this line so that
  /// the registry sees its own type. Context: loop (setup).
  template <class Registry>
  void enroll(Registry* registry, const char* instance_name) {
    registry->enroll(instance_name, *this);
  }

  /// Frame work: runs once per frame in the block's frame stage. Called by the engine only.
  /// Context: frame ISR.
  virtual void run() {}
  /// Kilohertz work: runs once per millisecond tick in the kilohertz stage. Called by the engine
  /// only. Default: run(), so a plugin written for the original (one run() for any rate) still
  /// works; blocks with work at both rates override both. Context: kilohertz ISR.
  virtual void run_kilohertz() { run(); }
  /// Runs once per dance_loop() (loop stage). Called by the engine only.
  virtual void loop() {}
  /// Called by the engine at start with the frame period it is about to run: a block that cannot
  /// work at that period reports why on the fault path and returns false, and the engine does
  /// not start. Default: any period. Context: loop.
  virtual bool accept_frame_period(uint32_t period_us) {
    (void)period_us;
    return true;
  }
  /// Called by the engine at start, once every block has accepted the frame period and before
  /// the stages are ordered: a block whose setup depends on what its ports are mapped to (the
  /// sketch's wiring) reads and checks it here; a block that cannot work with it reports why on
  /// the fault path and returns false, and the engine does not start. Default: any wiring.
  /// Context: loop.
  virtual bool check_wiring() { return true; }
  /// Whether `input`, one of this block's ports, drives a motor in steps, and if so the world
  /// units (mm) one step is: how an interface that speaks in motor steps finds its steps/mm
  /// through the port graph, without knowing the class. Default: false (no steps).
  /// Context: loop.
  virtual bool world_units_per_step(const BlockPort& input, double& world_units) const {
    (void)input;
    (void)world_units;
    return false;
  }

 protected:
  /// Unregisters the block. Blocks are never deleted through a Block pointer (they are globals
  /// or locals), so the destructor is not virtual: no operator delete reaches firmware images.
  ~Block() { unregister(this); }

  /// Registers this block in a stage. On a full registry it reports a fault and returns kFull;
  /// registering twice in one stage is a no-op. Context: loop.
  Status register_in(Stage stage);

 private:
  // Every virtual is defined inline, so Block has no key function and its vtable and type_info
  // are emitted wherever a subclass is compiled. Code built with RTTI (tests, host sketches) can
  // then derive from Block although the core itself is built with -fno-rtti.
  static void unregister(Block* block);
  static double absolute_value(BlockPort& port);

  bool enabled_ = true;
};

/// The original library's name for a block.
using Plugin = Block;

}  // namespace stepdance
