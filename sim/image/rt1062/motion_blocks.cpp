// The motion blocks, created and put on the bus together.
#include "image/rt1062/motion_blocks.hpp"

namespace stepdance::sim::image {

MotionBlocks::MotionBlocks(const PeripheralBus& bus, ChipContext& chip, BoardIo& io, TeensyModel model)
    : flexio3_(bus, chip, io, model),
      pwm_{{1, bus, chip}, {2, bus, chip}, {3, bus, chip}, {4, bus, chip}},
      capture_(bus, chip, pwm_[0], pwm_[1]),
      enc_{{0, bus, chip, io, xbar1_}, {1, bus, chip, io, xbar1_}} {
  xbar1_.add_listener([this] {
    enc_[0].routing_changed();
    enc_[1].routing_changed();
  });
}

std::unique_ptr<MotionBlocks> add_motion_blocks(PeripheralBus& bus, ChipContext& chip, BoardIo& io,
                                                TeensyModel model) {
  auto blocks = std::make_unique<MotionBlocks>(bus, chip, io, model);
  if (!bus.add(blocks->flexio3())) return nullptr;
  for (unsigned index = 0; index < 4; ++index) {
    if (!bus.add(blocks->flexpwm(index))) return nullptr;
  }
  if (!bus.add(blocks->xbar1()) || !bus.add(blocks->enc(0)) || !bus.add(blocks->enc(1))) return nullptr;
  return blocks;
}

}  // namespace stepdance::sim::image
