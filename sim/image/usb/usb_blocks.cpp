// Wiring of the USB blocks.
#include "image/usb/usb_blocks.hpp"

#include <cstdint>

namespace stepdance::sim::image::usb {

UsbBlocks::UsbBlocks(ChipContext& chip, BoardIo& world, HostOptions options)
    : controller(chip, phy), host(chip, world, controller, options) {
  controller.set_activity_listener([this] { host.wake(); });
}

std::unique_ptr<UsbBlocks> add_usb_blocks(PeripheralBus& bus, ChipContext& chip, BoardIo& world, HostOptions options) {
  auto blocks = std::make_unique<UsbBlocks>(chip, world, options);
  for (const Peripheral* block :
       {static_cast<Peripheral*>(&blocks->phy), static_cast<Peripheral*>(&blocks->controller)}) {
    for (const Peripheral* other : bus.blocks()) {
      const uint64_t begin = block->base(), end = begin + block->size_bytes();
      if (begin < uint64_t{other->base()} + other->size_bytes() && other->base() < end) return nullptr;
    }
  }
  bus.add(blocks->phy);
  bus.add(blocks->controller);
  blocks->host.start(chip.now_ns());
  return blocks;
}

}  // namespace stepdance::sim::image::usb
