// The state behind the Cortex-M7's system control space that more than one block shares.
#pragma once

#include <array>
#include <cstdint>

namespace stepdance::sim::image {

/// SCB, MPU, FPU and debug register values (DDI 0403E B3.2, B3.5, C1.6; Cortex-M7 TRM). The
/// register blocks read and write it; the CPU reads VTOR, CCR, SHCSR enables and fills the fault
/// status registers. Context: the simulator's thread.
struct CoreRegisters {
  uint32_t vtor = 0;                    ///< B3.2.5; the boot ROM leaves 0 … the image's startup sets it
  uint32_t scr = 0;                     ///< B3.2.7
  uint32_t ccr = 0x00040200;            ///< B3.2.8: Cortex-M7 reset value (BP, STKALIGN set; TRM 4.1)
  uint32_t cfsr = 0;                    ///< B3.2.15 (MMFSR, BFSR, UFSR)
  uint32_t hfsr = 0;                    ///< B3.2.16
  uint32_t mmfar = 0;                   ///< B3.2.17
  uint32_t bfar = 0;                    ///< B3.2.18
  uint32_t afsr = 0;                    ///< B3.2.19
  uint32_t cpacr = 0;                   ///< B3.2.20
  uint32_t actlr = 0;                   ///< B3.2.4 (Cortex-M7 TRM 3.3.4)
  uint32_t fpccr = 0xC0000000;          ///< B3.2.21: ASPEN | LSPEN at reset
  uint32_t fpcar = 0;                   ///< B3.2.22
  uint32_t fpdscr = 0;                  ///< B3.2.23
  uint32_t demcr = 0;                   ///< C1.6.5 (TRCENA bit 24)
  uint32_t dwt_ctrl = 0x40000000;       ///< C1.8.7: NUMCOMP = 4 (Cortex-M7 TRM 8.1)
  uint32_t dwt_cyccnt_written = 0;      ///< CYCCNT as last written (or at enable)
  uint64_t dwt_cyccnt_since = 0;        ///< core cycles when it was written or enabled
  bool dwt_counting = false;            ///< CTRL.CYCCNTENA (and TRCENA) were on since then
  uint32_t mpu_ctrl = 0;                ///< B3.5.7
  uint32_t mpu_rnr = 0;                 ///< B3.5.8
  std::array<uint32_t, 16> mpu_rbar{};  ///< B3.5.9 (Cortex-M7 has 16 regions: TRM 6.1)
  std::array<uint32_t, 16> mpu_rasr{};  ///< B3.5.10
  uint32_t mpu_generation = 0;          ///< bumped by every MPU register write (the CPU re-applies them)
  uint32_t csselr = 0;                  ///< B4.8.3 cache size selection
  uint64_t cache_operations = 0;        ///< writes to the cache maintenance registers, counted

  // CCR bits (B3.2.8).
  static constexpr uint32_t kCcrUnalignTrp = 1u << 3;
  static constexpr uint32_t kCcrDiv0Trp = 1u << 4;
  // SHCSR enable bits (B3.2.13).
  static constexpr uint32_t kMemFaultEna = 1u << 16;
  static constexpr uint32_t kBusFaultEna = 1u << 17;
  static constexpr uint32_t kUsgFaultEna = 1u << 18;
};

}  // namespace stepdance::sim::image
