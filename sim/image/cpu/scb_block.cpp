// System control block registers (DDI 0403E B3.2.2 table B3-4). Offsets are from 0xE000ED00.
#include "image/cpu/image_chip.hpp"
#include "image/cpu/system_blocks.hpp"

namespace stepdance::sim::image {
namespace {

constexpr uint32_t kCpuid = 0x00, kIcsr = 0x04, kVtor = 0x08, kAircr = 0x0C, kScr = 0x10, kCcr = 0x14;
constexpr uint32_t kShpr1 = 0x18, kShpr3End = 0x24, kShcsr = 0x24, kCfsr = 0x28, kHfsr = 0x2C;
constexpr uint32_t kMmfar = 0x34, kBfar = 0x38, kAfsr = 0x3C, kClidr = 0x78, kCtr = 0x7C;
constexpr uint32_t kCcsidr = 0x80, kCsselr = 0x84, kCpacr = 0x88;
/// Cortex-M7 r1p1 (the RT1062's core: IMXRT1060RM rev 3, 1.2; Cortex-M7 TRM 3.2 "CPUID").
constexpr uint32_t kCpuidValue = 0x411FC271;
/// Cache IDs of the RT1062's Cortex-M7 (32 KB I-cache, 32 KB D-cache: IMXRT1060RM 1.3;
/// encodings from the Cortex-M7 TRM 4.1.3 tables 4-3 to 4-5).
constexpr uint32_t kClidrValue = 0x09000003, kCtrValue = 0x8303C003;
constexpr uint32_t kCcsidrData = 0xF01FE019, kCcsidrInstruction = 0xF03FE019;
// AIRCR (B3.2.6): VECTKEY 0x05FA in writes, 0xFA05 in reads; PRIGROUP bits [10:8].
constexpr uint32_t kVectKey = 0x05FA0000, kVectKeyStat = 0xFA050000;

}  // namespace

uint32_t ScbBlock::icsr() const {
  // VECTACTIVE [8:0], RETTOBASE 11, VECTPENDING [20:12], ISRPENDING 22, PENDSTSET 26, PENDSVSET 28.
  uint32_t value = chip_.current_exception() & 0x1FF;
  if (state_.active_count() <= 1) value |= 1u << 11;
  const unsigned pending = state_.next_to_take(Masks{});
  value |= (pending & 0x1FF) << 12;
  for (unsigned n = kFirstIrq; n < kExceptionCount; ++n) {
    if (state_.pending(n)) value |= 1u << 22;
  }
  if (state_.pending(kSysTick)) value |= 1u << 26;
  if (state_.pending(kPendSv)) value |= 1u << 28;
  if (state_.pending(kNmi)) value |= 1u << 31;
  return value;
}

Access ScbBlock::write_icsr(uint32_t value) {
  if (value & (1u << 31)) chip_.pend_exception(kNmi);
  if (value & (1u << 28)) chip_.pend_exception(kPendSv);
  if (value & (1u << 27)) state_.set_pending(kPendSv, false);
  if (value & (1u << 26)) chip_.pend_exception(kSysTick);
  if (value & (1u << 25)) state_.set_pending(kSysTick, false);
  return Access::kOk;
}

Access ScbBlock::write_aircr(uint32_t value) {
  if ((value & 0xFFFF0000) != kVectKey) return Access::kOk;  // ignored without the key
  if (value & 0x4) return Access::kUnmodelled;               // SYSRESETREQ: a reset is not modelled
  state_.set_priority_group((value >> 8) & 7);
  return Access::kOk;
}

uint32_t ScbBlock::shcsr() const {
  // Active bits: MEMFAULTACT 0, BUSFAULTACT 1, USGFAULTACT 3, SVCALLACT 7, MONITORACT 8,
  // PENDSVACT 10, SYSTICKACT 11; pended: USGFAULTPENDED 12 … SVCALLPENDED 15; enables 16-18.
  uint32_t value = 0;
  const unsigned active_bits[][2] = {{kMemManage, 0},    {kBusFault, 1}, {kUsageFault, 3}, {kSvCall, 7},
                                     {kDebugMonitor, 8}, {kPendSv, 10},  {kSysTick, 11}};
  for (const auto& bit : active_bits) {
    if (state_.active(bit[0])) value |= 1u << bit[1];
  }
  if (state_.enabled(kMemManage)) value |= CoreRegisters::kMemFaultEna;
  if (state_.enabled(kBusFault)) value |= CoreRegisters::kBusFaultEna;
  if (state_.enabled(kUsageFault)) value |= CoreRegisters::kUsgFaultEna;
  return value;
}

void ScbBlock::write_shcsr(uint32_t value) {
  state_.set_enabled(kMemManage, (value & CoreRegisters::kMemFaultEna) != 0);
  state_.set_enabled(kBusFault, (value & CoreRegisters::kBusFaultEna) != 0);
  state_.set_enabled(kUsageFault, (value & CoreRegisters::kUsgFaultEna) != 0);
}

uint32_t ScbBlock::read_shpr(uint32_t offset) const {
  uint32_t value = 0;
  for (unsigned i = 0; i < 4; ++i) {
    const unsigned number = 4 + (offset - kShpr1) + i;  // SHPR1 byte 0 is MemManage (4)
    value |= static_cast<uint32_t>(state_.priority(number) & 0xFF) << (8 * i);
  }
  return value;
}

void ScbBlock::write_shpr(uint32_t offset, uint8_t bytes, uint32_t value) {
  for (unsigned i = 0; i < bytes; ++i) {
    const unsigned number = 4 + (offset - kShpr1) + i;
    // Reserved slots (7-10, 13) are RAZ/WI (B3.2.10-12).
    if (number == 7 || number == 8 || number == 9 || number == 10 || number == 13) continue;
    state_.set_priority(number, static_cast<uint8_t>(value >> (8 * i)));
  }
}

Access ScbBlock::read(uint32_t offset, uint8_t bytes, uint32_t& value) {
  if (offset >= kShpr1 && offset < kShpr3End) {
    value = read_shpr(offset & ~3u) >> (8 * (offset & 3));
    if (bytes < 4) value &= (1u << (8 * bytes)) - 1;
    return Access::kOk;
  }
  if (bytes != 4 && offset >= kCfsr && offset < kHfsr) {  // MMFSR, BFSR (bytes), UFSR (halfword)
    value = (core_.cfsr >> (8 * (offset - kCfsr))) & ((1u << (8 * bytes)) - 1);
    return Access::kOk;
  }
  if (bytes != 4) return Access::kUnmodelled;
  switch (offset) {
    case kCpuid: value = kCpuidValue; return Access::kOk;
    case kIcsr: value = icsr(); return Access::kOk;
    case kVtor: value = core_.vtor; return Access::kOk;
    case kAircr: value = kVectKeyStat | state_.priority_group() << 8; return Access::kOk;
    case kScr: value = core_.scr; return Access::kOk;
    case kCcr: value = core_.ccr; return Access::kOk;
    case kShcsr: value = shcsr(); return Access::kOk;
    case kCfsr: value = core_.cfsr; return Access::kOk;
    case kHfsr: value = core_.hfsr; return Access::kOk;
    case kMmfar: value = core_.mmfar; return Access::kOk;
    case kBfar: value = core_.bfar; return Access::kOk;
    case kAfsr: value = core_.afsr; return Access::kOk;
    case kClidr: value = kClidrValue; return Access::kOk;
    case kCtr: value = kCtrValue; return Access::kOk;
    case kCcsidr: value = (core_.csselr & 1) ? kCcsidrInstruction : kCcsidrData; return Access::kOk;
    case kCsselr: value = core_.csselr; return Access::kOk;
    case kCpacr: value = core_.cpacr; return Access::kOk;
    default: return Access::kUnmodelled;
  }
}

Access ScbBlock::write(uint32_t offset, uint8_t bytes, uint32_t value) {
  if (offset >= kShpr1 && offset < kShpr3End) {
    write_shpr(offset, bytes, value);
    chip_.pend_exception(0);
    return Access::kOk;
  }
  if (bytes != 4) return Access::kUnmodelled;
  switch (offset) {
    case kIcsr: return write_icsr(value);
    case kVtor: core_.vtor = value & 0xFFFFFF80; return Access::kOk;  // TBLOFF [31:7]
    case kAircr: return write_aircr(value);
    case kScr: core_.scr = value & 0x16; return Access::kOk;                  // SLEEPONEXIT, SLEEPDEEP, SEVONPEND
    case kCcr: core_.ccr = (value & 0x0007031B) | 0x200; return Access::kOk;  // STKALIGN reads one on M7
    case kShcsr:
      write_shcsr(value);
      chip_.pend_exception(0);
      return Access::kOk;
    case kCfsr: core_.cfsr &= ~value; return Access::kOk;  // write one to clear
    case kHfsr: core_.hfsr &= ~value; return Access::kOk;
    case kMmfar: core_.mmfar = value; return Access::kOk;
    case kBfar: core_.bfar = value; return Access::kOk;
    case kCsselr: core_.csselr = value & 0xF; return Access::kOk;
    case kCpacr: core_.cpacr = value & 0x00F00000; return Access::kOk;  // CP10, CP11 only
    default: return Access::kUnmodelled;
  }
}

}  // namespace stepdance::sim::image
