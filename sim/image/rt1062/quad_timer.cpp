// Quad timers TMR1..4: configuration storage (RM §54.9).
#include "image/rt1062/quad_timer.hpp"

namespace stepdance::sim::image::rt1062 {
namespace {

// 16-bit register index within a channel (offset / 2, RM §54.9).
constexpr uint32_t kCapt = 2, kHold = 4, kCntr = 5, kCtrl = 6, kSctrl = 7, kCsctrl = 10, kEnbl = 15;
constexpr uint16_t kSctrlInterrupts = (1u << 14) | (1u << 12) | (1u << 10);  // TCFIE, TOFIE, IEFIE
constexpr uint16_t kCsctrlInterrupts = (1u << 6) | (1u << 7);                // TCF1EN, TCF2EN

}  // namespace

QuadTimer::QuadTimer(unsigned number) : number_(number) { half_[kEnbl] = 0x000Fu; }

ClockGate QuadTimer::gate() const {
  constexpr int8_t kFields[5] = {0, 13, 14, 15, 8};
  return ClockGate{6, kFields[number_]};
}

bool QuadTimer::readable(uint32_t index) const {
  const uint32_t reg = index % 16u;
  const bool live = reg == kCapt || reg == kHold || reg == kCntr || reg == kSctrl || reg == kCsctrl;
  return !(live && counting(index / 16u));
}

bool QuadTimer::writable(uint32_t index, uint16_t value) const {
  const uint32_t reg = index % 16u;
  if (reg == kSctrl) return (value & kSctrlInterrupts) == 0;
  if (reg == kCsctrl) return (value & kCsctrlInterrupts) == 0;
  return true;
}

Access QuadTimer::read(uint32_t offset, uint8_t bytes, uint32_t& value) {
  if (offset + bytes > kSize) return Access::kUnmodelled;
  value = 0;
  for (uint32_t at = offset; at < offset + bytes; at += 2) {
    const uint32_t index = at / 2u;
    if (!readable(index)) return Access::kUnmodelled;
    const uint32_t half = bytes == 1 ? (half_[index] >> (8u * (at & 1u))) & 0xFFu : half_[index];
    value |= half << (8u * (at - offset));
  }
  return Access::kOk;
}

Access QuadTimer::write(uint32_t offset, uint8_t bytes, uint32_t value) {
  if (offset + bytes > kSize) return Access::kUnmodelled;
  for (uint32_t at = offset; at < offset + bytes; at += 2) {
    const uint32_t index = at / 2u;
    uint16_t half = static_cast<uint16_t>(value >> (8u * (at - offset)));
    if (bytes == 1) {
      const unsigned shift = 8u * (at & 1u);
      half = static_cast<uint16_t>((half_[index] & ~(0xFFu << shift)) | ((value & 0xFFu) << shift));
    }
    if (!writable(index, half)) return Access::kUnmodelled;
    half_[index] = half;
  }
  return Access::kOk;
}

}  // namespace stepdance::sim::image::rt1062
