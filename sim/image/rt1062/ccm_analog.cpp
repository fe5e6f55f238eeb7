// CCM_ANALOG: PLLs that lock after their lock time, PFDs and MISC registers (RM §14.8).
#include "image/rt1062/ccm_analog.hpp"

namespace stepdance::sim::image::rt1062 {
namespace {

// PLL register bits (RM §14.8.1 CCM_ANALOG_PLL_ARM, §14.8.2 PLL_USB1, §14.8.3 PLL_USB2,
// §14.8.4 PLL_SYS, §14.8.8 PLL_AUDIO, §14.8.11 PLL_VIDEO, §14.8.14 PLL_ENET).
constexpr uint32_t kLock = 1u << 31;           // LOCK, read only
constexpr uint32_t kBypass = 1u << 16;         // BYPASS: output = the bypass source (24 MHz)
constexpr uint32_t kEnable = 1u << 13;         // ENABLE: the clock output is on
constexpr uint32_t kPowerBit12 = 1u << 12;     // POWERDOWN (ARM, SYS, AUDIO, VIDEO, ENET) or POWER (USB)
constexpr uint32_t kArmDivSelectMask = 0x7Fu;  // PLL_ARM DIV_SELECT: Fout = 24 MHz × DIV / 2
constexpr uint32_t kUsbDivSelect = 1u << 1;    // PLL_USB DIV_SELECT: 0 = 480 MHz, 1 = 528 MHz
constexpr uint32_t kSysDivSelect = 1u << 0;    // PLL_SYS DIV_SELECT: 0 = 480 MHz, 1 = 528 MHz
constexpr uint32_t kPfdFracMask = 0x3Fu;       // PFDn_FRAC, per 8-bit PFD field: Fout = PLL × 18 / FRAC
constexpr uint32_t kPfdClockGate = 0x80u;      // PFDn_CLKGATE

// Lock times in 24 MHz reference cycles (data sheet IMXRT1060CEC §4.1 PLL tables; see header).
constexpr uint32_t kLockCycles[7] = {2250, 383, 383, 11250, 11250, 11250, 11250};

constexpr uint32_t kPllOffset[7] = {0x000, 0x010, 0x020, 0x030, 0x070, 0x0A0, 0x0E0};
constexpr uint32_t kPfd480 = 0x0F0;  // RM §14.8.15 CCM_ANALOG_PFD_480
constexpr uint32_t kPfd528 = 0x100;  // RM §14.8.16 CCM_ANALOG_PFD_528

SimTime lock_duration_ns(Pll pll) {
  return static_cast<SimTime>(kLockCycles[static_cast<size_t>(pll)]) * kSecond / kOscillatorHz;
}

}  // namespace

// Offsets and reset values: RM §14.8 (register map of CCM_ANALOG).
const std::array<CcmAnalog::Register, 20> CcmAnalog::kRegisters = {{
    {0x000, 0x00013063u, true},   // PLL_ARM (§14.8.1)
    {0x010, 0x00012000u, true},   // PLL_USB1 (§14.8.2)
    {0x020, 0x00012000u, true},   // PLL_USB2 (§14.8.3)
    {0x030, 0x00013001u, true},   // PLL_SYS (§14.8.4)
    {0x040, 0x00000000u, false},  // PLL_SYS_SS (§14.8.5)
    {0x050, 0x00000000u, false},  // PLL_SYS_NUM (§14.8.6)
    {0x060, 0x00000012u, false},  // PLL_SYS_DENOM (§14.8.7)
    {0x070, 0x00011006u, true},   // PLL_AUDIO (§14.8.8)
    {0x080, 0x05F5E100u, false},  // PLL_AUDIO_NUM (§14.8.9)
    {0x090, 0x2964619Cu, false},  // PLL_AUDIO_DENOM (§14.8.10)
    {0x0A0, 0x0001100Cu, true},   // PLL_VIDEO (§14.8.11)
    {0x0B0, 0x05F5E100u, false},  // PLL_VIDEO_NUM (§14.8.12)
    {0x0C0, 0x10A24447u, false},  // PLL_VIDEO_DENOM (§14.8.13)
    {0x0E0, 0x00011001u, true},   // PLL_ENET (§14.8.14)
    {0x0F0, 0x1311100Cu, true},   // PFD_480 (§14.8.15)
    {0x100, 0x1018101Bu, true},   // PFD_528 (§14.8.16)
    {0x150, 0x04000000u, true},   // MISC0 (§14.8.17; also PMU_MISC0, XTALOSC24M_MISC0)
    {0x160, 0x00000000u, true},   // MISC1 (§14.8.18)
    {0x170, 0x00272727u, true},   // MISC2 (§14.8.19)
    {0xFFF, 0, false},            // (end marker, never matched: offsets are word aligned)
}};

CcmAnalog::CcmAnalog(ChipContext& context) : context_(context), lock_event_([this] { changed(); }) {
  for (size_t i = 0; i < kRegisters.size(); ++i) values_[i] = kRegisters[i].reset;
  lock_at_ns_.fill(-1);  // every PLL is powered down at reset
}

int CcmAnalog::find(uint32_t offset) const {
  for (size_t i = 0; i + 1 < kRegisters.size(); ++i) {
    const Register& reg = kRegisters[i];
    if (offset >= reg.offset && offset < reg.offset + (reg.aliases ? 16u : 4u)) return static_cast<int>(i);
  }
  return -1;
}

bool CcmAnalog::covers(uint32_t offset) const { return find(offset) >= 0; }

uint32_t CcmAnalog::pll_register(Pll pll) const {
  return values_[static_cast<size_t>(find(kPllOffset[static_cast<size_t>(pll)]))];
}

bool CcmAnalog::powered(Pll pll, uint32_t value) const {
  const bool bit12 = (value & kPowerBit12) != 0;
  return (pll == Pll::kUsb1 || pll == Pll::kUsb2) ? bit12 : !bit12;
}

bool CcmAnalog::locked(Pll pll) const {
  const SimTime at = lock_at_ns_[static_cast<size_t>(pll)];
  return at >= 0 && context_.now_ns() >= at;
}

uint32_t CcmAnalog::value_at(uint32_t offset) const {
  const int index = find(offset & ~3u);
  if (index < 0) return 0;
  uint32_t value = values_[static_cast<size_t>(index)];
  for (size_t p = 0; p < 7; ++p) {
    if (kRegisters[static_cast<size_t>(index)].offset == kPllOffset[p]) {
      value = (value & ~kLock) | (locked(static_cast<Pll>(p)) ? kLock : 0u);
    }
  }
  return value;
}

Access CcmAnalog::read(uint32_t offset, uint8_t bytes, uint32_t& value) {
  if (find(offset) < 0) return Access::kUnmodelled;
  value = lane_read(value_at(offset), offset, bytes);
  return Access::kOk;
}

Access CcmAnalog::write(uint32_t offset, uint8_t bytes, uint32_t value) {
  const int index = find(offset);
  if (index < 0) return Access::kUnmodelled;
  const Register& reg = kRegisters[static_cast<size_t>(index)];
  const uint32_t old_value = values_[static_cast<size_t>(index)];
  const auto alias = static_cast<Alias>(((offset & ~3u) - reg.offset) / 4u);
  const uint32_t word = lane_merge(alias == Alias::kWrite ? old_value : 0u, offset, bytes, value);
  const uint32_t new_value = apply_alias(old_value, alias, word) & ~kLock;
  values_[static_cast<size_t>(index)] = new_value;
  for (size_t p = 0; p < 7; ++p) {
    if (reg.offset == kPllOffset[p]) write_pll(static_cast<Pll>(p), old_value, new_value);
  }
  changed();
  return Access::kOk;
}

// A PLL that powers up, or whose multiplier changes while powered, locks a lock time later.
void CcmAnalog::write_pll(Pll pll, uint32_t old_value, uint32_t new_value) {
  const size_t p = static_cast<size_t>(pll);
  const uint32_t divider = pll == Pll::kArm ? kArmDivSelectMask : pll == Pll::kSys ? kSysDivSelect : kUsbDivSelect;
  if (!powered(pll, new_value)) {
    lock_at_ns_[p] = -1;
    return;
  }
  const bool relock = !powered(pll, old_value) || ((old_value ^ new_value) & divider) != 0;
  if (!relock) return;
  lock_at_ns_[p] = context_.now_ns() + lock_duration_ns(pll);
  context_.scheduler().schedule(lock_event_, lock_at_ns_[p]);
}

void CcmAnalog::changed() {
  // The lock event serves every PLL: after it fires, requeue it for the next lock still ahead.
  SimTime next = -1;
  for (SimTime at : lock_at_ns_) {
    if (at > context_.now_ns() && (next < 0 || at < next)) next = at;
  }
  if (next >= 0) context_.scheduler().schedule(lock_event_, next);
  if (on_change_) on_change_();
}

void CcmAnalog::apply_boot_rom_state() {
  const size_t arm = static_cast<size_t>(find(kPllOffset[static_cast<size_t>(Pll::kArm)]));
  const size_t sys = static_cast<size_t>(find(kPllOffset[static_cast<size_t>(Pll::kSys)]));
  values_[arm] = kEnable | 66u;            // 24 MHz × 66 / 2 = 792 MHz, POWERDOWN and BYPASS clear
  values_[sys] = kEnable | kSysDivSelect;  // 528 MHz
  lock_at_ns_[static_cast<size_t>(Pll::kArm)] = 0;
  lock_at_ns_[static_cast<size_t>(Pll::kSys)] = 0;
  if (on_change_) on_change_();
}

uint32_t CcmAnalog::pll_hz(Pll pll) const {
  const uint32_t value = pll_register(pll);
  if ((value & kEnable) == 0) return 0;
  if (value & kBypass) return kOscillatorHz;
  if (!powered(pll, value) || !locked(pll)) return 0;
  switch (pll) {
    case Pll::kArm: return static_cast<uint32_t>(uint64_t{kOscillatorHz} * (value & kArmDivSelectMask) / 2u);
    case Pll::kUsb1:
    case Pll::kUsb2: return kOscillatorHz * ((value & kUsbDivSelect) ? 22u : 20u);
    case Pll::kSys: return kOscillatorHz * ((value & kSysDivSelect) ? 22u : 20u);
    default: return 0;
  }
}

uint32_t CcmAnalog::pfd_hz(Pll pll, unsigned index) const {
  const uint32_t pfd = values_[static_cast<size_t>(find(pll == Pll::kUsb1 ? kPfd480 : kPfd528))];
  const uint32_t field = (pfd >> (8u * (index & 3u))) & 0xFFu;
  const uint32_t frac = field & kPfdFracMask;
  if ((field & kPfdClockGate) || frac == 0) return 0;
  return static_cast<uint32_t>(uint64_t{pll_hz(pll)} * 18u / frac);
}

}  // namespace stepdance::sim::image::rt1062
