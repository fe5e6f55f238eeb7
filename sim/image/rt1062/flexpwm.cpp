// eFlexPWM registers (RM §55.8): decoding, write-one-to-clear flags, MCTRL's RUN/LDOK/CLDOK.
#include "image/rt1062/flexpwm.hpp"

#include "kernel/scheduler/scheduler.hpp"

namespace stepdance::sim::image {
namespace {

constexpr uint32_t kBases[4] = {0x403DC000u, 0x403E0000u, 0x403E4000u, 0x403E8000u};  // RM §2.3
constexpr const char* kNames[4] = {"PWM1", "PWM2", "PWM3", "PWM4"};
constexpr uint32_t kStride = 0x60u;  // submodule register blocks, RM §55.8

// Submodule register offsets (RM §55.8).
constexpr uint32_t kCnt = 0x00u, kCtrl = 0x06u, kSts = 0x24u, kInten = 0x26u, kDmaen = 0x28u;
constexpr uint32_t kCaptctrlA = 0x34u, kCaptctrlB = 0x38u, kCaptctrlX = 0x3Cu;
constexpr uint32_t kCval0 = 0x40u, kCval5Cyc = 0x56u;
constexpr uint32_t kReserved = 0x08u;  // between CTRL and VAL0
// Module registers: OUTEN 0x180 … FCTRL20 0x194; MCTRL 0x188 (RM §55.8).
constexpr uint32_t kModuleFirst = 0x180u, kModuleLast = 0x194u, kMctrl = 0x188u;
constexpr uint16_t kStsWritable = 0x7FFFu;  // RUF, REF, RF, CFA1 … CFX0, CMPF5..0 (w1c)
// INTEN: capture (CX0IE … CA1IE, bits 11:6) and RIE (bit 12) are modelled.
constexpr uint16_t kIntenModelled = 0x1FC0u;
// SMnCTRL reset value 0x0400 (FULL), DTCNTn 0x07FF, DISMAPn 0xFFFF (RM §55.8).
constexpr uint16_t kCtrlReset = 0x0400u;

}  // namespace

FlexPwm::FlexPwm(unsigned module, const PeripheralBus& bus, ChipContext& chip)
    : module_(module), bus_(bus), chip_(chip) {
  for (unsigned sm = 0; sm < kSubmodules; ++sm) {
    Submodule& s = sm_[sm];
    s.regs[kCtrl / 2] = kCtrlReset;
    s.regs[0x2C / 2] = s.regs[0x2E / 2] = 0xFFFFu;  // DISMAP0, DISMAP1
    s.regs[0x30 / 2] = s.regs[0x32 / 2] = 0x07FFu;  // DTCNT0, DTCNT1
    wake_[sm].owner = this;
    wake_[sm].sm = sm;
  }
}

FlexPwm::~FlexPwm() {
  for (Wake& wake : wake_) chip_.scheduler().cancel(wake);
}

const char* FlexPwm::name() const { return kNames[module_ - 1]; }
uint32_t FlexPwm::base() const { return kBases[module_ - 1]; }

unsigned FlexPwm::irq(unsigned sm) const {
  // RM §4.3 table 4-2: PWM1_0..3 102–105, PWM2_0..3 137–140, PWM3_0..3 142–145, PWM4_0..3 147–150.
  constexpr unsigned kFirst[4] = {102, 137, 142, 147};
  return kFirst[module_ - 1] + sm;
}

Access FlexPwm::read(uint32_t offset, uint8_t bytes, uint32_t& value) {
  if (bytes != 2) return Access::kUnmodelled;  // the registers are 16 bits wide
  if (offset < kSubmodules * kStride) return read_submodule(offset / kStride, offset % kStride, value);
  if (offset < kModuleFirst || offset > kModuleLast) return Access::kUnmodelled;
  if (offset == kMctrl) {
    for (unsigned sm = 0; sm < kSubmodules; ++sm) refresh(sm, chip_.now_ns());  // LDOK clears at a load
  }
  value = module_regs_[(offset - kModuleFirst) / 2];
  return Access::kOk;
}

Access FlexPwm::write(uint32_t offset, uint8_t bytes, uint32_t value) {
  if (bytes != 2) return Access::kUnmodelled;
  const uint16_t half = static_cast<uint16_t>(value);
  if (offset < kSubmodules * kStride) return write_submodule(offset / kStride, offset % kStride, half);
  if (offset < kModuleFirst || offset > kModuleLast) return Access::kUnmodelled;
  if (offset == kMctrl) return write_mctrl(half);
  module_regs_[(offset - kModuleFirst) / 2] = half;
  return Access::kOk;
}

Access FlexPwm::read_submodule(unsigned sm, uint32_t offset, uint32_t& value) {
  Submodule& s = sm_[sm];
  const SimTime now = chip_.now_ns();
  refresh(sm, now);
  if (offset == kReserved || offset > kCval5Cyc) return Access::kUnmodelled;
  if (offset == kCnt) {
    value = s.running ? counter(s, now) : s.held_count;
  } else if (offset == kSts) {
    value = status(sm, now);
  } else if (offset == kCaptctrlA || offset == kCaptctrlB || offset == kCaptctrlX) {
    value = read_captctrl(s.channel[offset == kCaptctrlA ? 0 : offset == kCaptctrlB ? 1 : 2]);
  } else if (offset >= kCval0) {
    // CVAL0/1 = X, CVAL2/3 = A, CVAL4/5 = B; reading CVALn pops its FIFO (RM §55.8 SMnCVALn).
    const unsigned n = (offset - kCval0) / 4;
    Channel& channel = s.channel[n < 2 ? 2 : n < 4 ? 0 : 1];
    const unsigned circuit = n % 2;
    const bool cycle = (offset - kCval0) % 4 != 0;
    value = cycle ? channel.cycle[circuit] : channel.value[circuit];
    if (!cycle) channel.full[circuit] = false;
  } else {
    value = s.regs[offset / 2];
  }
  return Access::kOk;
}

Access FlexPwm::write_submodule(unsigned sm, uint32_t offset, uint16_t value) {
  Submodule& s = sm_[sm];
  const SimTime now = chip_.now_ns();
  refresh(sm, now);
  if (offset == kReserved || offset > kCval5Cyc) return Access::kUnmodelled;
  if (offset == kCnt || offset >= kCval0) return Access::kOk;  // read-only: writes ignored
  if (offset == kSts) {
    clear_status(sm, value & kStsWritable, now);
  } else if (offset == kInten) {
    if (value & ~kIntenModelled) return Access::kUnmodelled;  // compare / reload-error interrupts
    s.regs[kInten / 2] = value;
  } else if (offset == kDmaen) {
    if (value != 0) return Access::kUnmodelled;  // no DMA
  } else if (offset == kCaptctrlA || offset == kCaptctrlB || offset == kCaptctrlX) {
    return write_captctrl(sm, offset == kCaptctrlA ? 0 : offset == kCaptctrlB ? 1 : 2, value);
  } else if (offset == kCtrl) {
    if (value >> 12) return Access::kUnmodelled;  // LDFQ: loads at every opportunity only
    s.regs[offset / 2] = value;
  } else {
    s.regs[offset / 2] = value;
  }
  settle(sm);
  return Access::kOk;
}

uint16_t FlexPwm::read_captctrl(const Channel& channel) const {
  // CAxCNT: words in the circuit's FIFO, bits 12:10 (circuit 0) and 15:13 (circuit 1).
  return static_cast<uint16_t>((channel.ctrl & 0x03FFu) | (channel.full[0] ? 1u << 10 : 0u) |
                               (channel.full[1] ? 1u << 13 : 0u));
}

Access FlexPwm::write_captctrl(unsigned sm, unsigned index, uint16_t value) {
  Channel& channel = sm_[sm].channel[index];
  // INP_SELx (bit 6, the edge counter as input) and EDGCNTx_EN (bit 7) are not modelled.
  if (value & 0x00C0u) return Access::kUnmodelled;
  const bool arming = (value & 1u) && !(channel.ctrl & 1u);
  channel.ctrl = static_cast<uint16_t>(value & 0x033Fu);  // ARM, ONESHOT, EDGx0, EDGx1, CFxWM
  if (arming) channel.next = 0;                           // circuit 0 is armed first
  return Access::kOk;
}

Access FlexPwm::write_mctrl(uint16_t value) {
  const SimTime now = chip_.now_ns();
  uint16_t& mctrl = module_regs_[(kMctrl - kModuleFirst) / 2];
  const uint16_t was = mctrl;
  // IPOL 15:12 and RUN 11:8 as written; CLDOK (7:4) clears LDOK; LDOK (3:0) is set by a 1.
  uint16_t next = static_cast<uint16_t>((value & 0xFF00u) | (was & 0x000Fu) | (value & 0x000Fu));
  next = static_cast<uint16_t>(next & ~((value >> 4) & 0x000Fu));
  mctrl = next;
  for (unsigned sm = 0; sm < kSubmodules; ++sm) {
    const uint16_t run = static_cast<uint16_t>(1u << (8 + sm));
    const uint16_t ldok = static_cast<uint16_t>(1u << sm);
    if ((next & run) && !(was & run)) {
      if (!start(sm, now)) {
        mctrl = was;
        return Access::kUnmodelled;  // counter clock not modelled (CLK_SEL, IPG unreadable)
      }
    } else if (!(next & run) && (was & run)) {
      stop(sm, now);
    } else if ((next & run) && (next & ldok) && !(was & ldok) && (sm_[sm].regs[kCtrl / 2] & 0x0400u)) {
      sm_[sm].load_pending = true;  // loads at the next full-cycle reload
      sm_[sm].load_at_ns = next_reload_ns(sm_[sm], now);
    }
    settle(sm);
  }
  return Access::kOk;
}

void FlexPwm::Wake::fire(Event& event, Scheduler& scheduler) {
  auto& wake = static_cast<Wake&>(event);
  wake.owner->refresh(wake.sm, scheduler.now());
  wake.owner->settle(wake.sm);
}

}  // namespace stepdance::sim::image
