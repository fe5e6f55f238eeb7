// The USB part of the chip in one call: USBPHY1, the USB1 controller and the emulated host.
#pragma once

#include <memory>

#include "image/chip/board_io.hpp"
#include "image/chip/chip_context.hpp"
#include "image/chip/peripheral_bus.hpp"
#include "image/usb/usb_controller.hpp"
#include "image/usb/usb_host.hpp"
#include "image/usb/usb_phy.hpp"

namespace stepdance::sim::image::usb {

/// Owns the USB blocks; the bus only refers to them, so this must outlive the bus's use.
struct UsbBlocks {
  UsbBlocks(ChipContext& chip, BoardIo& world, HostOptions options);
  UsbPhy phy;
  UsbController controller;
  UsbHost host;
};

/// Builds USBPHY1 and USB1, adds both to `bus`, connects the emulated host to the controller
/// and starts it at the chip's current time (it waits for the firmware to attach). Returns null
/// if either window overlaps a block already on the bus. Called once, before the image runs.
std::unique_ptr<UsbBlocks> add_usb_blocks(PeripheralBus& bus, ChipContext& chip, BoardIo& world,
                                          HostOptions options = {});

}  // namespace stepdance::sim::image::usb
