// The MPU regions and caches of the CI firmware image, as a Teensy 4 sets them (ARMv7-M ARM §B3.5
// MPU, §B2.2.7 cache maintenance; memory map: RM chapter 2 "Memory Maps").
//
// The higher region number wins where regions overlap. Region 0 maps the whole 4 GB as no-access,
// so every address outside the listed memories faults (the processor's system space, 0xE0000000
// up, is never subject to the MPU). Two 32-byte no-access traps sit on top: address 0 (a null
// pointer dereference) and the bottom of the stack (_stack_guard, just above .bss: the stack grows
// down into it and faults before it can overwrite variables).
#include <stdint.h>

#include "stand_in_registers.h"
#include "stand_in_startup.h"

extern "C" uint32_t _stack_guard[];  // targets/teensy/ld/imxrt1062_sections.ld, 32-byte aligned

namespace {

namespace mpu = stand_in::mpu;

// Memory types (ARMv7-M ARM §B3.5.9, TEX/C/B encodings).
constexpr uint32_t kStronglyOrdered = mpu::rasr_type(0, 0, 0);
constexpr uint32_t kDevice = mpu::rasr_type(2, 0, 0);  // non-shareable device
constexpr uint32_t kNormalUncached = mpu::rasr_type(1, 0, 0);
constexpr uint32_t kNormalWriteThrough = mpu::rasr_type(0, 1, 0);
constexpr uint32_t kNormalWriteBackAllocate = mpu::rasr_type(1, 1, 1);
// Access permissions (AP, §B3.5.8 Table B3-15): none, read/write, read-only.
constexpr uint32_t kNoAccess = mpu::rasr_access(0);
constexpr uint32_t kReadWrite = mpu::rasr_access(3);
constexpr uint32_t kReadOnly = mpu::rasr_access(7);
constexpr uint32_t kNoExecute = mpu::kRasrExecuteNever;

struct Region {
  uint32_t base;
  uint32_t attributes;
  uint8_t log2_bytes;
};

// In region-number order. Region 5's base is filled in at run time (the stack guard).
constexpr int kStackGuardRegion = 5;
constexpr Region kRegions[] = {
    {0x00000000u, kStronglyOrdered | kNoAccess | kNoExecute, 32},           // 0 everything else
    {0x00000000u, kNormalUncached | kReadOnly, 19},                         // 1 ITCM, 512 KB: code
    {0x00000000u, kDevice | kNoAccess | kNoExecute, 5},                     // 2 null pointer trap
    {0x00200000u, kNormalWriteThrough | kReadOnly, 17},                     // 3 boot ROM, 128 KB
    {0x20000000u, kNormalUncached | kReadWrite | kNoExecute, 19},           // 4 DTCM, 512 KB
    {0x00000000u, kStronglyOrdered | kNoAccess | kNoExecute, 5},            // 5 stack guard
    {0x20200000u, kNormalWriteBackAllocate | kReadWrite | kNoExecute, 20},  // 6 OCRAM, 1 MB
    {0x40000000u, kDevice | kReadWrite | kNoExecute, 26},                   // 7 peripherals, 64 MB
    {0x60000000u, kNormalWriteBackAllocate | kReadOnly, 24},                // 8 QSPI flash, 16 MB
};

STAND_IN_FLASH void program_regions() {
  stand_in::reg32(mpu::kCtrl) = 0;
  stand_in::barrier();
  uint32_t number = 0;
  for (const Region& region : kRegions) {
    const uint32_t base =
        number == kStackGuardRegion ? static_cast<uint32_t>(reinterpret_cast<uintptr_t>(_stack_guard)) : region.base;
    stand_in::reg32(mpu::kRbar) = base | mpu::kRbarValid | number;
    stand_in::reg32(mpu::kRasr) = region.attributes | mpu::rasr_size(region.log2_bytes) | mpu::kRasrEnable;
    ++number;
  }
  stand_in::barrier();
  stand_in::reg32(mpu::kCtrl) = mpu::kCtrlEnable;
  stand_in::barrier();
}

// The RT1062's L1 data cache: 32 KB, 4 ways, 32-byte lines, so 256 sets (RM §1.3 features;
// Cortex-M7 cache geometry). DCISW takes the way in bits 31:30 and the set in bits 12:5.
constexpr uint32_t kDataCacheWays = 4;
constexpr uint32_t kDataCacheSets = 256;

STAND_IN_FLASH void enable_caches() {
  namespace scb = stand_in::scb;
  if ((stand_in::reg32(scb::kCcr) & scb::kCcrDataCache) == 0) {
    // Invalidate the whole data cache before turning it on (ARMv7-M ARM §B2.2.7): its contents
    // after reset are not defined.
    for (uint32_t way = 0; way < kDataCacheWays; ++way) {
      for (uint32_t set = 0; set < kDataCacheSets; ++set) stand_in::reg32(scb::kDcisw) = way << 30 | set << 5;
    }
  }
  stand_in::barrier();
  stand_in::reg32(scb::kIciallu) = 0;
  stand_in::barrier();
  stand_in::reg32(scb::kCcr) |= scb::kCcrInstructionCache | scb::kCcrDataCache;
  stand_in::barrier();
}

}  // namespace

extern "C" STAND_IN_FLASH void stand_in_memory_protection_start() {
  program_regions();
  enable_caches();
}
