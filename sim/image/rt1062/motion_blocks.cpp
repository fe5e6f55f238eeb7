// The motion blocks, created and put on the bus together.
#include "image/rt1062/motion_blocks.hpp"

#include <vector>

namespace stepdance::sim::image {

MotionBlocks::MotionBlocks(const PeripheralBus& bus, ChipContext& chip, BoardIo& io, TeensyModel model)
    : flexio3_(bus, chip, io, model),
      pwm_{{1, bus, chip}, {2, bus, chip}, {3, bus, chip}, {4, bus, chip}},
      capture_(bus, chip, pwm_[0], pwm_[1]),
      enc_{{0, bus, chip, io, xbar1_}, {1, bus, chip, io, xbar1_}},
      lpi2c_{{1, bus, chip, io}, {3, bus, chip, io}} {
  xbar1_.add_listener([this] {
    enc_[0].routing_changed();
    enc_[1].routing_changed();
  });
  for (Enc& enc : enc_) xbar1_.on_output_edge(enc.trigger_output(), [&enc] { enc.trigger(); });
}

namespace {

bool overlaps(const PeripheralBus& bus, const Peripheral& block) {
  const uint64_t first = block.base();
  const uint64_t last = first + block.size_bytes() - 1;
  for (const Peripheral* other : bus.blocks()) {
    const uint64_t other_first = other->base();
    const uint64_t other_last = other_first + other->size_bytes() - 1;
    if (first <= other_last && other_first <= last) return true;
  }
  return false;
}

}  // namespace

std::unique_ptr<MotionBlocks> add_motion_blocks(PeripheralBus& bus, ChipContext& chip, BoardIo& io, TeensyModel model) {
  auto blocks = std::make_unique<MotionBlocks>(bus, chip, io, model);
  std::vector<Peripheral*> all = {&blocks->flexio3(), &blocks->xbar1(),  &blocks->enc(0),
                                  &blocks->enc(1),    &blocks->lpi2c(0), &blocks->lpi2c(1)};
  for (unsigned index = 0; index < 4; ++index) all.push_back(&blocks->flexpwm(index));
  for (const Peripheral* block : all) {
    if (overlaps(bus, *block)) return nullptr;
  }
  for (Peripheral* block : all) bus.add(*block);
  return blocks;
}

}  // namespace stepdance::sim::image
