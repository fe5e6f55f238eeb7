// The stack: its bottom, overflow into data, and a backtrace walked from it.
#include <unicorn/unicorn.h>

#include <cstdio>

#include "image/cpu/image_chip.hpp"

namespace stepdance::sim::image {
namespace {

constexpr size_t kMaxFrames = 16;
constexpr uint32_t kMaxScanBytes = 8192;

// True if the halfwords before `return_address` (Thumb bit clear) are a BL or BLX (register):
// the word on the stack is then a return address, not data (DDI 0403E A6.7.18, A6.7.20).
bool follows_call(ImageChip& chip, uint32_t return_address) {
  uint16_t before[2] = {0, 0};
  if (!chip.read_memory(return_address - 4, before, 4)) return false;
  const bool bl = (before[0] & 0xF800) == 0xF000 && (before[1] & 0xD000) == 0xD000;
  const bool blx = (before[1] & 0xFF87) == 0x4780;
  return bl || blx;
}

std::string frame_line(const ElfSymbols& symbols, uint32_t address) {
  char text[16];
  std::snprintf(text, sizeof text, "0x%08X", address);
  const std::string name = symbols.describe(address);
  return name.empty() ? std::string(text) : std::string(text) + " " + name;
}

}  // namespace

std::vector<std::string> ImageChip::backtrace(uint32_t pc, uint32_t lr, uint32_t sp) const {
  auto& chip = const_cast<ImageChip&>(*this);
  std::vector<std::string> frames{frame_line(image_.symbols, pc)};
  const bool lr_is_code = (lr & 1u) != 0 && lr < 0xF0000000 && in_memory(lr & ~1u, 2);
  if (lr_is_code && follows_call(chip, lr & ~1u)) frames.push_back(frame_line(image_.symbols, lr & ~1u));
  // Scan the stack for words that are return addresses into code (a heuristic without unwind
  // tables: a stale return address left in a frame can appear).
  for (uint32_t at = sp & ~3u; at - (sp & ~3u) < kMaxScanBytes && frames.size() < kMaxFrames; at += 4) {
    uint32_t word = 0;
    if (!chip.read_memory(at, &word, 4)) break;
    if ((word & 1u) == 0 || word == lr) continue;
    const uint32_t address = word & ~1u;
    if (image_.symbols.function_at(address) == nullptr || !follows_call(chip, address)) continue;
    frames.push_back(frame_line(image_.symbols, address));
  }
  return frames;
}

// The stack's bottom: the top of the firmware's MPU guard region if it set one (Teensyduino 1.59
// puts a 32-byte no-access region at _ebss), else `_ebss` (the stack grows down toward .bss in
// DTCM: Teensyduino's imxrt1062*.ld), else nothing (0: not checked).
uint32_t ImageChip::stack_limit() const {
  if (stack_limit_generation_ == core_.mpu_generation) return stack_limit_;
  stack_limit_generation_ = core_.mpu_generation;
  stack_limit_ = compute_stack_limit();
  return stack_limit_;
}

uint32_t ImageChip::compute_stack_limit() const {
  uint32_t limit = 0;
  image_.symbols.find("_ebss", limit);
  if ((core_.mpu_ctrl & 1) == 0) return limit;
  for (size_t region = 0; region < core_.mpu_rasr.size(); ++region) {
    const uint32_t rasr = core_.mpu_rasr[region];
    const bool enabled = (rasr & 1) != 0, no_access = ((rasr >> 24) & 7) == 0;
    const uint32_t size_bytes = 2u << ((rasr >> 1) & 0x1F);
    const uint32_t base = core_.mpu_rbar[region] & ~31u;
    if (enabled && no_access && size_bytes <= 1024 && base >= 0x20000000 && base < 0x20080000) {
      if (base + size_bytes > limit) limit = base + size_bytes;
    }
  }
  return limit;
}

// SP below the bottom (by less than 1 MB: a wild SP elsewhere is a different fault).
bool ImageChip::stack_overflows(uint32_t sp) const {
  const uint32_t limit = stack_limit();
  return limit != 0 && sp < limit && limit - sp <= (1u << 20);
}

// At a block after one that lowered SP: has the main stack gone below its bottom? (Checked after
// every block that pushes or allocates a frame: the overflowing frame's own stores may already
// have reached the data below, as on a chip without a guard region that catches them.)
bool ImageChip::stack_pointer_overflowed(uint32_t address) {
  check_sp_ = false;
  // Only the main stack has that bottom: a thread on PSP (CONTROL.SPSEL) runs on a stack of its own.
  if (current_exception_ == 0 && (read_register(UC_ARM_REG_CONTROL) & 2u) != 0) return false;
  const uint32_t sp = read_register(UC_ARM_REG_SP);
  if (!stack_overflows(sp)) return false;
  block_address_ = address;
  stack_fault(sp, address);
  return true;
}

void ImageChip::stack_fault(uint32_t sp, uint32_t pc) {
  char what[160];
  std::snprintf(what, sizeof what, "stack overflow: the stack pointer 0x%08X is below the stack's bottom 0x%08X", sp,
                stack_limit());
  if (stack_overflows(sp)) {
    raise_fault(ImageStop::Kind::kStackOverflow, what, pc);
    return;
  }
  core_.cfsr |= 1u << 12;  // BFSR.STKERR
  std::snprintf(what, sizeof what, "BusFault: stacking an exception frame at 0x%08X, where no memory is", sp);
  raise_fault(ImageStop::Kind::kBusFault, what, pc);
}

}  // namespace stepdance::sim::image
