// The MPU as the emulator's page protections (DDI 0403E B3.5: regions, priority by number,
// subregions, AP and XN), at the emulator's page granularity: a region decides a page only if
// it covers the whole page, so regions smaller than a page (Teensyduino's 32-byte guards) are
// not enforced this way — the stack guard is checked from SP instead (cpu_stack.cpp).
#include <unicorn/unicorn.h>

#include <cstdio>

#include "image/cpu/image_chip.hpp"

namespace stepdance::sim::image {
namespace {

constexpr uint32_t kMpuEnable = 1u << 0, kPrivDefEna = 1u << 2;

// The protection region `rasr` gives (AP B3.5.9 table B3-15, XN): we always run privileged.
uint32_t protection_of(uint32_t rasr) {
  const uint32_t ap = (rasr >> 24) & 7;
  uint32_t prot = 0;
  if (ap != 0 && ap != 4) prot |= uint32_t{UC_PROT_READ};
  if (ap >= 1 && ap <= 3) prot |= uint32_t{UC_PROT_WRITE};
  if ((rasr & (1u << 28)) == 0 && prot != 0) prot |= uint32_t{UC_PROT_EXEC};
  return prot;
}

// True if enabled region (rbar, rasr) covers [page, page + page_bytes) with an enabled subregion.
bool covers(uint32_t rbar, uint32_t rasr, uint64_t page, uint64_t page_bytes) {
  if ((rasr & 1) == 0) return false;
  const uint64_t size = uint64_t{2} << ((rasr >> 1) & 0x1F);
  const uint64_t base = rbar & ~(size - 1) & ~uint64_t{31};
  if (page < base || page + page_bytes > base + size) return false;
  if (size < 256) return true;  // no subregions below 256 bytes
  const uint64_t sub = size / 8;
  const uint64_t first = (page - base) / sub, last = (page + page_bytes - 1 - base) / sub;
  for (uint64_t s = first; s <= last; ++s) {
    if (rasr & (1u << (8 + s))) return false;  // SRD: this subregion is disabled
  }
  return true;
}

}  // namespace

// The protection of one page: the highest-numbered region covering it, else the default map
// (PRIVDEFENA) or no access; with the MPU off, `natural`.
uint32_t ImageChip::page_protection(uint64_t page, uint64_t page_bytes, uint32_t natural) const {
  if ((core_.mpu_ctrl & kMpuEnable) == 0) return natural;
  for (int region = 15; region >= 0; --region) {
    if (covers(core_.mpu_rbar[region], core_.mpu_rasr[region], page, page_bytes)) {
      return protection_of(core_.mpu_rasr[region]) & natural;
    }
  }
  return (core_.mpu_ctrl & kPrivDefEna) != 0 ? natural : uint32_t{0};
}

// Re-applies the MPU to every page of RAM and flash (between runs: protections change the
// emulator's translations).
void ImageChip::apply_mpu() {
  mpu_applied_ = core_.mpu_generation;
  uint32_t page_bytes = 0;
  uc_ctl_get_page_size(uc_, &page_bytes);
  if (page_bytes == 0) return;
  for (const MemoryWindow& memory : memories()) {
    uint64_t run_start = memory.base;
    uint32_t run_prot = page_protection(memory.base, page_bytes, memory.natural);
    for (uint64_t page = memory.base; page <= uint64_t{memory.base} + memory.size_bytes; page += page_bytes) {
      const bool end = page == uint64_t{memory.base} + memory.size_bytes;
      const uint32_t prot = end ? uint32_t{0xFFFFFFFF} : page_protection(page, page_bytes, memory.natural);
      if (prot == run_prot) continue;
      uc_mem_protect(uc_, run_start, page - run_start, run_prot);
      run_start = page;
      run_prot = prot;
    }
  }
}

// A protection fault: the MPU forbids it (MemManage), or a write to flash (BusFault).
void ImageChip::protection_fault(int type, uint32_t address, int size) {
  const bool fetch = type == UC_MEM_FETCH_PROT, write = type == UC_MEM_WRITE_PROT;
  const uint32_t pc = fetch ? address : note_access_position(address);
  char what[160];
  if ((core_.mpu_ctrl & kMpuEnable) != 0) {
    core_.cfsr |= fetch ? 1u << 0 : (1u << 1) | (1u << 7);  // MMFSR.IACCVIOL, or DACCVIOL + MMARVALID
    if (!fetch) core_.mmfar = address;
    std::snprintf(what, sizeof what, "MemManage: %s of %d bytes at 0x%08X, which the MPU forbids",
                  fetch   ? "instruction fetch"
                  : write ? "write"
                          : "read",
                  size, address);
    fault(kMemManage, what, pc);
    return;
  }
  core_.cfsr |= (1u << 9) | (1u << 15);
  core_.bfar = address;
  std::snprintf(what, sizeof what, "BusFault: write of %d bytes at 0x%08X (flash is read-only)", size, address);
  fault(kBusFault, what, pc);
}

}  // namespace stepdance::sim::image
