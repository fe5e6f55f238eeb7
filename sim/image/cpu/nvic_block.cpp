// NVIC registers (DDI 0403E B3.4.2 table B3-8). Offsets are from 0xE000E100.
#include "image/cpu/image_chip.hpp"
#include "image/cpu/system_blocks.hpp"

namespace stepdance::sim::image {
namespace {

// Register groups: ISER 0x000, ICER 0x080, ISPR 0x100, ICPR 0x180, IABR 0x200 (8 words each,
// words 5..7 beyond the RT1062's 160 lines read as zero and ignore writes), IPR 0x300..0x3EF.
constexpr uint32_t kIser = 0x000, kIcer = 0x080, kIspr = 0x100, kIcpr = 0x180, kIabr = 0x200, kIpr = 0x300;

uint32_t bits_of(const ExceptionState& state, unsigned word, bool (ExceptionState::*get)(unsigned) const) {
  uint32_t value = 0;
  for (unsigned bit = 0; bit < 32; ++bit) {
    const unsigned irq = word * 32 + bit;
    if (irq < kIrqCount && (state.*get)(kFirstIrq + irq)) value |= 1u << bit;
  }
  return value;
}

}  // namespace

Access NvicBlock::read(uint32_t offset, uint8_t bytes, uint32_t& value) {
  if (offset >= kIpr) {
    const unsigned first = offset - kIpr;
    value = 0;
    for (unsigned i = 0; i < bytes; ++i) {
      if (first + i < kIrqCount) value |= static_cast<uint32_t>(state_.priority(kFirstIrq + first + i)) << (8 * i);
    }
    return Access::kOk;
  }
  if (bytes != 4 || offset % 4 != 0 || offset >= kIabr + 0x20 || offset % 0x80 >= 0x20) return Access::kUnmodelled;
  const unsigned word = (offset % 0x80) / 4;
  switch (offset / 0x80 * 0x80) {
    case kIser:
    case kIcer: value = bits_of(state_, word, &ExceptionState::enabled); return Access::kOk;
    case kIspr:
    case kIcpr: value = bits_of(state_, word, &ExceptionState::pending); return Access::kOk;
    case kIabr: value = bits_of(state_, word, &ExceptionState::active); return Access::kOk;
    default: return Access::kUnmodelled;
  }
}

Access NvicBlock::write(uint32_t offset, uint8_t bytes, uint32_t value) {
  if (offset >= kIpr) {
    const unsigned first = offset - kIpr;
    for (unsigned i = 0; i < bytes; ++i) {
      if (first + i < kIrqCount) state_.set_priority(kFirstIrq + first + i, static_cast<uint8_t>(value >> (8 * i)));
    }
    return Access::kOk;
  }
  if (bytes != 4 || offset % 4 != 0 || offset >= kIabr || offset % 0x80 >= 0x20) return Access::kUnmodelled;
  const unsigned word = (offset % 0x80) / 4;
  const uint32_t group = offset / 0x80 * 0x80;
  for (unsigned bit = 0; bit < 32; ++bit) {
    const unsigned irq = word * 32 + bit;
    if ((value & (1u << bit)) == 0 || irq >= kIrqCount) continue;
    if (group == kIser || group == kIcer) state_.set_enabled(kFirstIrq + irq, group == kIser);
    if (group == kIspr || group == kIcpr) state_.set_pending(kFirstIrq + irq, group == kIspr);
  }
  chip_.pend_exception(0);  // re-evaluate: an enable or a pend may make an interrupt takeable
  return Access::kOk;
}

}  // namespace stepdance::sim::image
