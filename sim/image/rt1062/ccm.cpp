// CCM: clock gates and clock roots (RM §14.7).
#include "image/rt1062/ccm.hpp"

#include "image/rt1062/register_bits.hpp"

namespace stepdance::sim::image::rt1062 {
namespace {

struct CcmRegister {
  uint32_t offset;
  uint32_t reset;
  uint32_t read_only;  // bits a write leaves alone
};

// Offsets and reset values: RM §14.7 (CCM memory map). CSR's COSC_READY (bit 5) reads 1: the
// 24 MHz oscillator runs before the boot ROM starts the image (the manual's reset value, 0x10,
// is the state before it settles).
constexpr CcmRegister kRegisters[] = {
    {0x00, 0x0401107Fu, 0},            // CCR (§14.7.1)
    {0x08, 0x00000030u, 0xFFFFFFFFu},  // CSR (§14.7.2), read only
    {0x0C, 0x00000100u, 0},            // CCSR (§14.7.3): PLL3_SW_CLK_SEL bit 0
    {0x10, 0x00000001u, 0},            // CACRR (§14.7.4): ARM_PODF bits 2:0
    {0x14, 0x000A8300u, 0},            // CBCDR (§14.7.5)
    {0x18, 0x2DAE8324u, 0},            // CBCMR (§14.7.6)
    {0x1C, 0x04900000u, 0},            // CSCMR1 (§14.7.7)
    {0x20, 0x13192F06u, 0},            // CSCMR2 (§14.7.8)
    {0x24, 0x06490B00u, 0},            // CSCDR1 (§14.7.9)
    {0x28, 0x0EC102C1u, 0},            // CS1CDR (§14.7.10)
    {0x2C, 0x007336C1u, 0},            // CS2CDR (§14.7.11)
    {0x30, 0x33F71F92u, 0},            // CDCDR (§14.7.12)
    {0x38, 0x00029150u, 0},            // CSCDR2 (§14.7.13)
    {0x3C, 0x00030841u, 0},            // CSCDR3 (§14.7.14)
    {0x48, 0x00000000u, 0xFFFFFFFFu},  // CDHIPR (§14.7.15): handshakes complete at once
    {0x54, 0x00000079u, 0},            // CLPCR (§14.7.16)
    {0x58, 0x00000000u, 0xFFFFFFFFu},  // CISR (§14.7.17): no interrupt sources modelled
    {0x5C, 0xFFFFFFFFu, 0},            // CIMR (§14.7.18)
    {0x60, 0x000A0001u, 0},            // CCOSR (§14.7.19)
    {0x64, 0x0000FE62u, 0},            // CGPR (§14.7.20)
    {0x68, 0xFFFFFFFFu, 0},            // CCGR0 (§14.7.21)
    {0x6C, 0xFFFFFFFFu, 0},            // CCGR1 (§14.7.22)
    {0x70, 0xFC3FFFFFu, 0},            // CCGR2 (§14.7.23)
    {0x74, 0xFFFFFFCFu, 0},            // CCGR3 (§14.7.24)
    {0x78, 0xFFFFFFFFu, 0},            // CCGR4 (§14.7.25)
    {0x7C, 0xFFFFFFFFu, 0},            // CCGR5 (§14.7.26)
    {0x80, 0xFFFFFFFFu, 0},            // CCGR6 (§14.7.27)
    {0x84, 0xFFFFFFFFu, 0},            // CCGR7 (§14.7.28)
    {0x88, 0xFFFFFFFFu, 0},            // CMEOR (§14.7.29)
};
constexpr size_t kCount = sizeof(kRegisters) / sizeof(kRegisters[0]);

constexpr uint32_t kCcsr = 0x0C, kCacrr = 0x10, kCbcdr = 0x14, kCbcmr = 0x18, kCscmr1 = 0x1C, kCscmr2 = 0x20,
                   kCs1cdr = 0x28, kCcgr0 = 0x68;

constexpr uint32_t field(uint32_t value, unsigned shift, uint32_t mask) { return (value >> shift) & mask; }

}  // namespace

Ccm::Ccm(ChipContext& context, CcmAnalog& analog) : context_(context), analog_(analog) {
  for (size_t i = 0; i < kCount; ++i) values_[i] = kRegisters[i].reset;
  analog_.set_change_listener([this] { recompute(); });
  last_rates_ = rates();
}

int Ccm::find(uint32_t offset) const {
  for (size_t i = 0; i < kCount; ++i) {
    if (kRegisters[i].offset == (offset & ~3u)) return static_cast<int>(i);
  }
  return -1;
}

uint32_t Ccm::register_value(uint32_t offset) const {
  const int index = find(offset);
  return index < 0 ? 0 : values_[static_cast<size_t>(index)];
}

Access Ccm::read(uint32_t offset, uint8_t bytes, uint32_t& value) {
  const int index = find(offset);
  if (index < 0) return Access::kUnmodelled;
  value = lane_read(values_[static_cast<size_t>(index)], offset, bytes);
  return Access::kOk;
}

Access Ccm::write(uint32_t offset, uint8_t bytes, uint32_t value) {
  const int index = find(offset);
  if (index < 0) return Access::kUnmodelled;
  const size_t i = static_cast<size_t>(index);
  const uint32_t merged = lane_merge(values_[i], offset, bytes, value);
  values_[i] = (values_[i] & kRegisters[i].read_only) | (merged & ~kRegisters[i].read_only);
  recompute();
  return Access::kOk;
}

bool Ccm::gate_on(ClockGate gate) const {
  if (gate.ccgr < 0) return true;
  if (gate.ccgr > 7 || gate.field < 0 || gate.field > 15) return false;
  const uint32_t ccgr = register_value(kCcgr0 + 4u * static_cast<uint32_t>(gate.ccgr));
  return field(ccgr, 2u * static_cast<unsigned>(gate.field), 3u) != 0;
}

// PERIPH_CLK (RM §14.4 figure 14-2, clock tree): CBCDR PERIPH_CLK_SEL (bit 25) picks
// PRE_PERIPH_CLK (CBCMR PRE_PERIPH_CLK_SEL bits 19:18: PLL2, PLL2 PFD2, PLL2 PFD0, PLL1 / ARM_PODF)
// or PERIPH_CLK2 (CBCMR PERIPH_CLK2_SEL bits 13:12: PLL3_SW_CLK, OSC, PLL2 bypass; divided by
// CBCDR PERIPH_CLK2_PODF bits 29:27 + 1).
uint32_t Ccm::periph_clock_hz() const {
  const uint32_t cbcdr = register_value(kCbcdr), cbcmr = register_value(kCbcmr);
  if (field(cbcdr, 25, 1)) {
    uint32_t source = kOscillatorHz;
    switch (field(cbcmr, 12, 3)) {
      case 0:  // PLL3_SW_CLK: CCSR PLL3_SW_CLK_SEL 0 = PLL3 main clock, 1 = its bypass (24 MHz)
        source = field(register_value(kCcsr), 0, 1) ? kOscillatorHz : analog_.pll_hz(Pll::kUsb1);
        break;
      case 1: source = kOscillatorHz; break;
      default:  // PLL2 bypass clock: the 24 MHz reference
        source = kOscillatorHz;
        break;
    }
    return source / (field(cbcdr, 27, 7) + 1u);
  }
  switch (field(cbcmr, 18, 3)) {
    case 0: return analog_.pll_hz(Pll::kSys);
    case 1: return analog_.pfd_hz(Pll::kSys, 2);
    case 2: return analog_.pfd_hz(Pll::kSys, 0);
    default: return analog_.pll_hz(Pll::kArm) / (field(register_value(kCacrr), 0, 7) + 1u);
  }
}

// AHB = PERIPH_CLK / (CBCDR AHB_PODF bits 12:10 + 1); IPG = AHB / (IPG_PODF bits 9:8 + 1);
// PERCLK = (CSCMR1 PERCLK_CLK_SEL bit 6 ? OSC : IPG) / (PERCLK_PODF bits 5:0 + 1). RM §14.7.5, §14.7.7.
ClockRates Ccm::rates() const {
  const uint32_t cbcdr = register_value(kCbcdr), cscmr1 = register_value(kCscmr1);
  ClockRates rates;
  rates.core_hz = periph_clock_hz() / (field(cbcdr, 10, 7) + 1u);
  rates.ipg_hz = rates.core_hz / (field(cbcdr, 8, 3) + 1u);
  const uint32_t perclk_source = field(cscmr1, 6, 1) ? kOscillatorHz : rates.ipg_hz;
  rates.perclk_hz = perclk_source / (field(cscmr1, 0, 0x3F) + 1u);
  return rates;
}

// FLEXIO2_CLK_SEL (CSCMR2 bits 20:19): 0 PLL4 (audio), 1 PLL3 PFD2, 2 PLL5 (video), 3 PLL3_SW_CLK.
uint32_t Ccm::flexio2_clock_hz() const {
  const uint32_t cs1cdr = register_value(kCs1cdr);
  uint32_t source = 0;
  switch (field(register_value(kCscmr2), 19, 3)) {
    case 1: source = analog_.pfd_hz(Pll::kUsb1, 2); break;
    case 3: source = field(register_value(kCcsr), 0, 1) ? kOscillatorHz : analog_.pll_hz(Pll::kUsb1); break;
    default:
      source = analog_.pll_hz(Pll::kAudio);  // not modelled as a clock: 0
      break;
  }
  return source / (field(cs1cdr, 9, 7) + 1u) / (field(cs1cdr, 25, 7) + 1u);
}

void Ccm::apply_boot_rom_state() {
  values_[static_cast<size_t>(find(kCbcdr))] = (register_value(kCbcdr) & ~(3u << 8)) | (2u << 8);
  recompute();
}

void Ccm::add_rates_listener(std::function<void(const ClockRates&)> listener) {
  listeners_.push_back(std::move(listener));
  listeners_.back()(rates());
}

void Ccm::recompute() {
  const ClockRates now = rates();
  const bool same =
      now.core_hz == last_rates_.core_hz && now.ipg_hz == last_rates_.ipg_hz && now.perclk_hz == last_rates_.perclk_hz;
  last_rates_ = now;
  if (same) return;
  for (const auto& listener : listeners_) listener(now);
}

}  // namespace stepdance::sim::image::rt1062
