// USBPHY1 (RM ch. 43): PWD and CTRL, each at base +0 with SET (+4), CLR (+8) and TOG (+0xC).
#include "image/usb/usb_phy.hpp"

#include <cstdio>

namespace stepdance::sim::image::usb {

uint32_t* UsbPhy::register_at(uint32_t base_offset) {
  if (base_offset == kPwd) return &pwd_;
  if (base_offset == kCtrl) return &ctrl_;
  return nullptr;
}

Access UsbPhy::read(uint32_t offset, uint8_t bytes, uint32_t& value) {
  uint32_t* reg = register_at(offset & ~0xFu);
  if (reg == nullptr || bytes != 4) return Access::kUnmodelled;
  value = *reg;  // the SET/CLR/TOG aliases read the register too
  return Access::kOk;
}

Access UsbPhy::write(uint32_t offset, uint8_t bytes, uint32_t value) {
  uint32_t* reg = register_at(offset & ~0xFu);
  if (reg == nullptr || bytes != 4) return Access::kUnmodelled;
  const bool was_in_reset = (ctrl_ & kCtrlSoftReset) != 0;
  switch (offset & 0xFu) {
    case 0x0: *reg = value; break;
    case 0x4: *reg |= value; break;
    case 0x8: *reg &= ~value; break;
    default: *reg ^= value; break;
  }
  // SFTRST resets PWD, TX, RX and CTRL (RM: USBPHYx_CTRL SFTRST); held while it stays 1.
  if (!was_in_reset && (ctrl_ & kCtrlSoftReset)) apply_soft_reset();
  return Access::kOk;
}

void UsbPhy::apply_soft_reset() {
  pwd_ = kPwdResetValue;
  ctrl_ = kCtrlResetValue;
}

bool UsbPhy::ready() const { return not_ready_reason().empty(); }

std::string UsbPhy::not_ready_reason() const {
  char text[96];
  if (ctrl_ & kCtrlSoftReset) return "USBPHY1_CTRL.SFTRST is 1 (the PHY is held in reset)";
  if (ctrl_ & kCtrlClockGate) return "USBPHY1_CTRL.CLKGATE is 1 (the PHY's clocks are gated)";
  if (pwd_ & kPwdPowerDowns) {
    std::snprintf(text, sizeof text, "USBPHY1_PWD is 0x%08X (receivers or transmitters powered down)", pwd_);
    return text;
  }
  return "";
}

}  // namespace stepdance::sim::image::usb
