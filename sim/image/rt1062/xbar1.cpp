// XBARA1 registers (RM §61.4).
#include "image/rt1062/xbar1.hpp"

namespace stepdance::sim::image {
namespace {

constexpr uint32_t kSelLast = 0x82u;        // SEL65
constexpr uint32_t kCtrl0 = 0x84u;          // CTRL0, CTRL1 at 0x86
constexpr uint16_t kCtrlEnables = 0x0303u;  // DENn (DMA) and IENn (interrupt) of both outputs
constexpr uint16_t kCtrlFlags = 0x1010u;    // STSn, write 1 to clear

}  // namespace

Access Xbar1::read(uint32_t offset, uint8_t bytes, uint32_t& value) {
  if (bytes != 2) return Access::kUnmodelled;  // 16-bit registers
  if (offset <= kSelLast) {
    const unsigned output = offset;  // SELn at 2n holds outputs 2n and 2n + 1
    value = select_[output] | (static_cast<uint32_t>(select_[output + 1]) << 8);
    return Access::kOk;
  }
  if (offset == kCtrl0 || offset == kCtrl0 + 2) {
    value = ctrl_[(offset - kCtrl0) / 2];
    return Access::kOk;
  }
  return Access::kUnmodelled;
}

Access Xbar1::write(uint32_t offset, uint8_t bytes, uint32_t value) {
  if (bytes != 2) return Access::kUnmodelled;
  if (offset <= kSelLast) {
    select_[offset] = static_cast<uint8_t>(value & 0x7Fu);
    select_[offset + 1] = static_cast<uint8_t>((value >> 8) & 0x7Fu);
    for (const Listener& listener : listeners_) listener();
    return Access::kOk;
  }
  if (offset == kCtrl0 || offset == kCtrl0 + 2) {
    if (value & kCtrlEnables) return Access::kUnmodelled;  // no edge-detect DMA or interrupts
    uint16_t& ctrl = ctrl_[(offset - kCtrl0) / 2];
    ctrl = static_cast<uint16_t>((value & 0x0C0Cu) | (ctrl & kCtrlFlags & ~value));  // EDGEn; STSn w1c
    return Access::kOk;
  }
  return Access::kUnmodelled;
}

}  // namespace stepdance::sim::image

namespace stepdance::sim::image {

void Xbar1::pulse(uint8_t input) const {
  for (const EdgeListener& edge : edge_listeners_) {
    if (edge.output < kOutputs && select_[edge.output] == input) edge.listener();
  }
}

}  // namespace stepdance::sim::image
