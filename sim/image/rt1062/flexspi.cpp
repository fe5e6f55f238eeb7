// FlexSPI register storage and instant IP commands (RM §27.7).
#include "image/rt1062/flexspi.hpp"

#include "image/rt1062/register_bits.hpp"

namespace stepdance::sim::image::rt1062 {
namespace {

// Offsets (RM §27.7) and the reset values Teensyduino's startup may read back.
constexpr uint32_t kMcr0 = 0x000, kMcr1 = 0x004, kMcr2 = 0x008, kAhbcr = 0x00C, kIntr = 0x014, kLutKey = 0x018,
                   kLutCr = 0x01C, kIpcr1 = 0x0A4, kIpcmd = 0x0B0, kSts0 = 0x0E0, kRfdr0 = 0x100, kTfdr0 = 0x180;
constexpr uint32_t kIntrIpCmdDone = 1u << 0, kIntrIpRxWatermark = 1u << 5;

}  // namespace

FlexSpi::FlexSpi(unsigned number) : number_(number) {
  regs_[kMcr0 / 4] = 0xFFFF80C2u;  // RM §27.7.1.1
  regs_[kMcr1 / 4] = 0xFFFFFFFFu;
  regs_[kMcr2 / 4] = 0x200081F7u;
  regs_[kAhbcr / 4] = 0x00000018u;
  regs_[kLutKey / 4] = 0x5AF05AF0u;
  regs_[kLutCr / 4] = 0x00000002u;
}

Access FlexSpi::read(uint32_t offset, uint8_t bytes, uint32_t& value) {
  const uint32_t word = offset & ~3u;
  if (word >= 0x300u) return Access::kUnmodelled;
  uint32_t result = regs_[word / 4u];
  if (word == kSts0) result = 0x3u;                           // SEQIDLE | ARBIDLE
  if (word >= kRfdr0 && word < kTfdr0) result = 0xFFFFFFFFu;  // nothing answers: pull-ups
  value = lane_read(result, offset, bytes);
  return Access::kOk;
}

Access FlexSpi::write(uint32_t offset, uint8_t bytes, uint32_t value) {
  const uint32_t word = offset & ~3u;
  if (word >= 0x300u) return Access::kUnmodelled;
  uint32_t& reg = regs_[word / 4u];
  if (word == kIntr) {
    reg &= ~lane_merge(0u, offset, bytes, value);  // write 1 to clear
    return Access::kOk;
  }
  if (word == kIpcmd && (lane_merge(0u, offset, bytes, value) & 1u)) {
    if (number_ == 1) return Access::kUnmodelled;            // flash IP commands are not modelled
    const bool reads = (regs_[kIpcr1 / 4u] & 0xFFFFu) != 0;  // IDATSZ: data to transfer
    regs_[kIntr / 4u] |= kIntrIpCmdDone | (reads ? kIntrIpRxWatermark : 0u);
    return Access::kOk;
  }
  reg = lane_merge(reg, offset, bytes, value);
  if (word == kMcr0) reg &= ~1u;  // SWRESET completes at once
  return Access::kOk;
}

}  // namespace stepdance::sim::image::rt1062
