// The USB blocks on a fake chip with the scripted device stack: what each USB test starts from.
#pragma once

#include <memory>

#include "fake_chip.hpp"
#include "fake_device_stack.hpp"
#include "image/chip/peripheral_bus.hpp"
#include "image/usb/usb_blocks.hpp"

namespace stepdance::sim::image::usb::testing {

struct UsbBench {
  explicit UsbBench(HostOptions options = {})
      : blocks(add_usb_blocks(bus, chip, world, options)), stack(chip, blocks->controller, blocks->phy) {}

  /// Initialises the stack, runs to enumeration's end and checks that it ended well.
  void enumerate() {
    stack.init();
    stack.run_until(300 * kMillisecond);
    ASSERT_EQ(host().failure(), "");
    ASSERT_TRUE(host().enumerated());
  }
  UsbHost& host() { return blocks->host; }
  UsbController& usb() { return blocks->controller; }

  FakeChip chip;
  FakeWorld world;
  PeripheralBus bus;
  std::unique_ptr<UsbBlocks> blocks;
  FakeDeviceStack stack;
};

}  // namespace stepdance::sim::image::usb::testing
