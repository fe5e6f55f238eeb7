// KinematicsCoreXY: maps cartesian x, y onto the two belt motors of a CoreXY / H-bot machine.
#pragma once

#include "stepdance/core/block.hpp"
#include "stepdance/core/block_port.hpp"
#include "stepdance/core/status.hpp"
#include "stepdance/core/units.hpp"

namespace stepdance {

/// CoreXY kinematics: a = x + y, b = x − y (forward, every frame), x = (a + b)/2,
/// y = (a − b)/2 (inverse, only for deep synchronisation). No scale factor in either direction.
///
///   input_x ─┐          ┌─► output_a  (→ channel A)
///            ├─ a, b ───┤
///   input_y ─┘          └─► output_b  (→ channel B)
///
/// Units: the maths is done in world units; each port converts with its own ratio, so giving a
/// port a ratio never mixes units (world units in, world units out).
class KinematicsCoreXY : public Block {
 public:
  /// The class name, for reports. Context: any.
  const char* type_name() const override { return "KinematicsCoreXY"; }
  KinematicsCoreXY();

  /// Begins the ports (inputs: INPUT with this block as parent; outputs: OUTPUT) and registers
  /// the block in the pre-channel stage. kFull if that registry is full. Context: loop.
  Status begin();

  /// Publishes its names under "<instance_name>." in `registry`, an RPC, which lists them
  /// (docs/rpc.md): the same as registry->enroll(instance_name, *this). Context: loop (setup).
  template <class Registry>
  void enroll(Registry* registry, const char* instance_name) {
    registry->enroll(instance_name, *this);
  }
  /// One frame: pull and update both inputs, set a and b, push both outputs. Context: frame ISR.
  void run() override;

  /// Deep push (an input was just reset): resets both outputs to a, b and pushes them deep
  /// downstream, without motion. Context: loop or frame ISR (called by BlockPort::push_deep).
  void push_deep() override;
  /// Deep pull: pulls both outputs from downstream, then resets x = (a + b)/2, y = (a − b)/2
  /// without motion. Context: as push_deep().
  void pull_deep() override;
  /// Deep read of input_x or input_y: x or y derived from the outputs' deep reads, in world
  /// units, changing nothing. Any other port: its own absolute value. Context: any.
  double read_deep(BlockPort& port) override;

  BlockPort input_x;
  BlockPort input_y;
  BlockPort output_a;
  BlockPort output_b;

 private:
  void reset_inputs_from(double a_world, double b_world);

  DecimalPosition position_x_ = 0;
  DecimalPosition position_y_ = 0;
  DecimalPosition position_a_ = 0;
  DecimalPosition position_b_ = 0;
};

}  // namespace stepdance
