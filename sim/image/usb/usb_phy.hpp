// USBPHY1: the USB 2.0 PHY's power-down and control registers, as far as a device stack uses them.
#pragma once

#include <cstdint>
#include <string>

#include "image/chip/peripheral.hpp"
#include "image/usb/usb_registers.hpp"

namespace stepdance::sim::image::usb {

/// RM ch. 43 (USBPHY): PWD and CTRL with their SET/CLR/TOG aliases. The PHY carries the bus
/// only when it is out of soft reset, its clocks are not gated and its receivers and
/// transmitters are powered; the controller asks ready() before it attaches. Other registers
/// (TX, RX, STATUS, DEBUG, VERSION) are not modelled. Simulator thread only.
class UsbPhy : public Peripheral {
 public:
  static constexpr uint32_t kPwd = 0x00;   // USBPHYx_PWD, reset 0x001E1C00
  static constexpr uint32_t kCtrl = 0x30;  // USBPHYx_CTRL, reset 0xC0200000
  static constexpr uint32_t kPwdResetValue = 0x001E1C00u;
  static constexpr uint32_t kCtrlResetValue = 0xC0200000u;
  static constexpr uint32_t kCtrlSoftReset = 1u << 31;  // SFTRST
  static constexpr uint32_t kCtrlClockGate = 1u << 30;  // CLKGATE
  /// TXPWDFS 10, TXPWDIBIAS 11, TXPWDV2I 12, RXPWDENV 17, RXPWD1PT1 18, RXPWDDIFF 19, RXPWDRX 20.
  static constexpr uint32_t kPwdPowerDowns = 0x001E1C00u;

  const char* name() const override { return "USBPHY1"; }
  uint32_t base() const override { return kUsbPhy1Base; }
  uint32_t size_bytes() const override { return kUsbPhy1SizeBytes; }
  Access read(uint32_t offset, uint8_t bytes, uint32_t& value) override;
  Access write(uint32_t offset, uint8_t bytes, uint32_t value) override;

  /// True when the PHY can carry the bus.
  bool ready() const;
  /// Why it cannot ("USBPHY1_CTRL.CLKGATE is 1", …); "" when ready.
  std::string not_ready_reason() const;

 private:
  uint32_t* register_at(uint32_t base_offset);
  void apply_soft_reset();

  uint32_t pwd_ = kPwdResetValue;
  uint32_t ctrl_ = kCtrlResetValue;
};

}  // namespace stepdance::sim::image::usb
