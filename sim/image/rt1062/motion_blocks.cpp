// The motion blocks, created and put on the bus together.
#include "image/rt1062/motion_blocks.hpp"

namespace stepdance::sim::image {

MotionBlocks::MotionBlocks(const PeripheralBus& bus, ChipContext& chip, BoardIo& io, TeensyModel model)
    : flexio3_(bus, chip, io, model) {}

std::unique_ptr<MotionBlocks> add_motion_blocks(PeripheralBus& bus, ChipContext& chip, BoardIo& io,
                                                TeensyModel model) {
  auto blocks = std::make_unique<MotionBlocks>(bus, chip, io, model);
  if (!bus.add(blocks->flexio3())) return nullptr;
  return blocks;
}

}  // namespace stepdance::sim::image
