// The smaller system-space blocks: SCS (ICTR, ACTLR), MPU, CoreDebug, STIR/FPU/cache, DWT.
#include "image/cpu/image_chip.hpp"
#include "image/cpu/system_blocks.hpp"

namespace stepdance::sim::image {

// ---- SCS: ICTR 0x004 (B3.4.4: INTLINESNUM 4 = 160 lines), ACTLR 0x008 (Cortex-M7 TRM 3.3.4).
Access ScsBlock::read(uint32_t offset, uint8_t bytes, uint32_t& value) {
  if (bytes != 4) return Access::kUnmodelled;
  if (offset == 0x4) {
    value = (kIrqCount / 32) - 1;
    return Access::kOk;
  }
  if (offset == 0x8) {
    value = core_.actlr;
    return Access::kOk;
  }
  return Access::kUnmodelled;
}

Access ScsBlock::write(uint32_t offset, uint8_t bytes, uint32_t value) {
  if (bytes != 4 || offset != 0x8) return Access::kUnmodelled;
  core_.actlr = value;
  return Access::kOk;
}

// ---- MPU (B3.5.5 table B3-11): TYPE 0x0 (DREGION 16), CTRL 0x4, RNR 0x8, RBAR 0xC, RASR 0x10,
// aliases RBAR_A1..A3 / RASR_A1..A3 at 0x14..0x28.
Access MpuBlock::read(uint32_t offset, uint8_t bytes, uint32_t& value) {
  if (bytes != 4) return Access::kUnmodelled;
  const unsigned region = core_.mpu_rnr & 0xF;
  switch (offset) {
    case 0x0: value = 16u << 8; return Access::kOk;
    case 0x4: value = core_.mpu_ctrl; return Access::kOk;
    case 0x8: value = core_.mpu_rnr; return Access::kOk;
    case 0xC:
    case 0x14:
    case 0x1C:
    case 0x24: value = core_.mpu_rbar[region] | region; return Access::kOk;
    case 0x10:
    case 0x18:
    case 0x20:
    case 0x28: value = core_.mpu_rasr[region]; return Access::kOk;
    default: return Access::kUnmodelled;
  }
}

Access MpuBlock::write(uint32_t offset, uint8_t bytes, uint32_t value) {
  if (bytes != 4) return Access::kUnmodelled;
  ++core_.mpu_generation;
  switch (offset) {
    case 0x4: core_.mpu_ctrl = value & 0x7; return Access::kOk;
    case 0x8: core_.mpu_rnr = value & 0xFF; return Access::kOk;
    case 0xC:
    case 0x14:
    case 0x1C:
    case 0x24:
      if (value & 0x10) core_.mpu_rnr = value & 0xF;  // VALID: the region field selects
      core_.mpu_rbar[core_.mpu_rnr & 0xF] = value & 0xFFFFFFE0;
      return Access::kOk;
    case 0x10:
    case 0x18:
    case 0x20:
    case 0x28: core_.mpu_rasr[core_.mpu_rnr & 0xF] = value; return Access::kOk;
    default: return Access::kUnmodelled;
  }
}

// ---- CoreDebug (C1.6.1 table C1-6): DEMCR 0xC. No debugger: DHCSR and the rest are unmodelled.
Access DebugBlock::read(uint32_t offset, uint8_t bytes, uint32_t& value) {
  if (bytes != 4 || offset != 0xC) return Access::kUnmodelled;
  value = core_.demcr;
  return Access::kOk;
}

Access DebugBlock::write(uint32_t offset, uint8_t bytes, uint32_t value) {
  if (bytes != 4 || offset != 0xC) return Access::kUnmodelled;
  const uint32_t count = dwt_.cyccnt();  // TRCENA gates CYCCNT: keep its value across the change
  core_.demcr = value & 0x010F07F1;
  dwt_.restart_count(count);
  return Access::kOk;
}

// ---- 0xE000EF00: STIR 0x00 (B3.4.3), FPCCR 0x34, FPCAR 0x38, FPDSCR 0x3C, MVFR0-2 0x40-0x48
// (B3.2.21-23, B4.6; values of the Cortex-M7 double-precision FPU, TRM 7.2), cache maintenance
// 0x50-0x78 (B4.8.1 table B4-19: ICIALLU, ICIMVAU, DCIMVAC, DCISW, DCCMVAU, DCCMVAC, DCCSW,
// DCCIMVAC, DCCISW, BPIALL) — write-only; accepted and counted (no cache is modelled).
Access ScbExtraBlock::read(uint32_t offset, uint8_t bytes, uint32_t& value) {
  if (bytes != 4) return Access::kUnmodelled;
  switch (offset) {
    case 0x34: value = core_.fpccr; return Access::kOk;
    case 0x38: value = core_.fpcar; return Access::kOk;
    case 0x3C: value = core_.fpdscr; return Access::kOk;
    case 0x40: value = 0x10110221; return Access::kOk;
    case 0x44: value = 0x12000011; return Access::kOk;
    case 0x48: value = 0x00000040; return Access::kOk;
    default: return Access::kUnmodelled;
  }
}

Access ScbExtraBlock::write(uint32_t offset, uint8_t bytes, uint32_t value) {
  if (bytes != 4) return Access::kUnmodelled;
  if (offset == 0x00) {
    chip_.pend_exception(kFirstIrq + (value & 0x1FF) < kExceptionCount ? kFirstIrq + (value & 0x1FF) : 0);
    return Access::kOk;
  }
  if (offset >= 0x50 && offset <= 0x78 && offset != 0x54) {
    ++core_.cache_operations;
    return Access::kOk;
  }
  switch (offset) {
    case 0x34: core_.fpccr = (core_.fpccr & 0x3FFFFFFF) | (value & 0xC0000000); return Access::kOk;
    case 0x38: core_.fpcar = value & ~7u; return Access::kOk;
    case 0x3C: core_.fpdscr = value & 0x07C00000; return Access::kOk;
    default: return Access::kUnmodelled;
  }
}

// ---- DWT (C1.8.6 table C1-21): CTRL 0x0, CYCCNT 0x4, LAR 0xFB0 (CoreSight lock, write-only).
uint32_t DwtBlock::cyccnt() const {
  if (!core_.dwt_counting) return core_.dwt_cyccnt_written;
  return static_cast<uint32_t>(core_.dwt_cyccnt_written + (chip_.cycles() - core_.dwt_cyccnt_since));
}

void DwtBlock::restart_count(uint32_t value) {
  core_.dwt_cyccnt_written = value;
  core_.dwt_cyccnt_since = chip_.cycles();
  core_.dwt_counting = (core_.dwt_ctrl & 1) != 0 && (core_.demcr & (1u << 24)) != 0;
}

Access DwtBlock::read(uint32_t offset, uint8_t bytes, uint32_t& value) {
  if (bytes != 4) return Access::kUnmodelled;
  if (offset == 0x0) {
    value = core_.dwt_ctrl;
    return Access::kOk;
  }
  if (offset == 0x4) {
    value = cyccnt();
    return Access::kOk;
  }
  return Access::kUnmodelled;
}

Access DwtBlock::write(uint32_t offset, uint8_t bytes, uint32_t value) {
  if (bytes != 4) return Access::kUnmodelled;
  if (offset == 0xFB0) return Access::kOk;
  if (offset == 0x0) {
    const uint32_t now = cyccnt();
    core_.dwt_ctrl = (core_.dwt_ctrl & 0xF0000000) | (value & 0x0FFFFFFF);
    restart_count(now);
    return Access::kOk;
  }
  if (offset == 0x4) {
    restart_count(value);
    return Access::kOk;
  }
  return Access::kUnmodelled;
}

SystemBlocks::SystemBlocks(ImageChip& chip, ExceptionState& state, CoreRegisters& core)
    : scs_(core),
      systick_(chip),
      nvic_(chip, state),
      scb_(chip, state, core),
      mpu_(core),
      debug_(core, dwt_),
      extra_(chip, core),
      dwt_(chip, core) {}

void SystemBlocks::add_to(PeripheralBus& bus) {
  for (Peripheral* block :
       std::initializer_list<Peripheral*>{&scs_, &systick_, &nvic_, &scb_, &mpu_, &debug_, &extra_, &dwt_}) {
    bus.add(*block);
  }
}

}  // namespace stepdance::sim::image
