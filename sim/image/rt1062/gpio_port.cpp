// GPIO1..9 registers (RM §12.5).
#include "image/rt1062/gpio_port.hpp"

#include "image/rt1062/register_bits.hpp"

namespace stepdance::sim::image::rt1062 {
namespace {

// Register offsets (RM §12.5, GPIO memory map; reset values all 0).
constexpr uint32_t kDr = 0x00, kGdir = 0x04, kPsr = 0x08, kIcr1 = 0x0C, kIcr2 = 0x10, kImr = 0x14, kIsr = 0x18,
                   kEdgeSel = 0x1C, kDrSet = 0x84, kDrClear = 0x88, kDrToggle = 0x8C;

// Bases (RM table 2-2) and gates (RM §14.7.21–24: GPIO1 CCGR1 CG13, GPIO2 CCGR0 CG15, GPIO3 CCGR2
// CG13, GPIO4 CCGR3 CG6, GPIO5 CCGR1 CG15). The fast GPIO6..9 sit on the CM7's AHB and have no
// CCGR gate of their own (none is listed for them in §14.7).
constexpr uint32_t kBases[10] = {0,           0x401B8000u, 0x401BC000u, 0x401C0000u, 0x401C4000u,
                                 0x400C0000u, 0x42000000u, 0x42004000u, 0x42008000u, 0x4200C000u};
constexpr ClockGate kGates[10] = {{}, {1, 13}, {0, 15}, {2, 13}, {3, 6}, {1, 15}, {}, {}, {}, {}};

}  // namespace

GpioPort::GpioPort(unsigned number, GpioPadSide& side) : number_(number), side_(side) {}

uint32_t GpioPort::base() const { return kBases[number_]; }
ClockGate GpioPort::gate() const { return kGates[number_]; }

Access GpioPort::read(uint32_t offset, uint8_t bytes, uint32_t& value) {
  uint32_t word = 0;
  switch (offset & ~3u) {
    case kDr:  // an input bit reads the pad (RM §12.5.1)
      word = (dr_ & gdir_) | (side_.pad_levels(number_) & ~gdir_);
      break;
    case kGdir: word = gdir_; break;
    case kPsr:
      word = side_.pad_levels(number_);
      sample(word);
      break;
    case kIcr1: word = icr1_; break;
    case kIcr2: word = icr2_; break;
    case kImr: word = imr_; break;
    case kIsr: word = isr_; break;
    case kEdgeSel: word = edge_sel_; break;
    case kDrSet:
    case kDrClear:
    case kDrToggle: word = 0; break;  // write-only: read 0 (RM §12.5.9–11)
    default: return Access::kUnmodelled;
  }
  value = lane_read(word, offset, bytes);
  return Access::kOk;
}

bool GpioPort::write_word(uint32_t word, uint32_t value) {
  switch (word) {
    case kDr: dr_ = value; return true;
    case kGdir: gdir_ = value; return true;
    case kDrSet: dr_ |= value; return true;
    case kDrClear: dr_ &= ~value; return true;
    case kDrToggle: dr_ ^= value; return true;
    default: return false;
  }
}

Access GpioPort::write(uint32_t offset, uint8_t bytes, uint32_t value) {
  const uint32_t word = offset & ~3u;
  const bool aliased = word == kDrSet || word == kDrClear || word == kDrToggle;
  const uint32_t current = word == kDr ? dr_ : word == kGdir ? gdir_ : 0u;
  const uint32_t merged = lane_merge(aliased ? 0u : current, offset, bytes, value);
  if (write_word(word, merged)) {
    side_.outputs_changed(number_);
    return Access::kOk;
  }
  switch (word) {
    case kPsr: return Access::kOk;  // read only: writes ignored (RM §12.5.3)
    case kIcr1: icr1_ = lane_merge(icr1_, offset, bytes, value); break;
    case kIcr2: icr2_ = lane_merge(icr2_, offset, bytes, value); break;
    case kImr: imr_ = lane_merge(imr_, offset, bytes, value); break;
    case kIsr: isr_ &= ~lane_merge(0u, offset, bytes, value); break;  // write 1 to clear
    case kEdgeSel: edge_sel_ = lane_merge(edge_sel_, offset, bytes, value); break;
    default: return Access::kUnmodelled;
  }
  sample(side_.pad_levels(number_));  // a level still held flags again at once
  side_.interrupts_changed();
  return Access::kOk;
}

// The ISR bits the change from `before` to `after` (and the levels now held) raise.
uint32_t GpioPort::detect(uint32_t before, uint32_t after) const {
  const uint32_t rose = ~before & after, fell = before & ~after;
  uint32_t flagged = edge_sel_ & (rose | fell);
  for (unsigned bit = 0; bit < 32; ++bit) {
    const uint32_t mask = 1u << bit;
    if (edge_sel_ & mask) continue;
    const uint32_t icr = ((bit < 16 ? icr1_ >> (2u * bit) : icr2_ >> (2u * (bit - 16u)))) & 3u;
    const bool hit = icr == 0   ? !(after & mask)
                     : icr == 1 ? (after & mask) != 0
                     : icr == 2 ? (rose & mask) != 0
                                : (fell & mask) != 0;
    if (hit) flagged |= mask;
  }
  return flagged;
}

void GpioPort::sample(uint32_t levels) {
  isr_ |= detect(sampled_ ? last_levels_ : levels, levels);  // no edge before the first sample
  sampled_ = true;
  last_levels_ = levels;
}

}  // namespace stepdance::sim::image::rt1062
