// Clock roots from the CCM's registers (RM chapter 14).
#include "image/rt1062/clock_roots.hpp"

namespace stepdance::sim::image {
namespace {

constexpr uint32_t kCcmCbcdr = 0x400FC014u;       // RM §14.7.5, CCM_CBCDR
constexpr uint32_t kCcmCscmr2 = 0x400FC020u;      // RM §14.7.8, CCM_CSCMR2
constexpr uint32_t kCcmCs1cdr = 0x400FC028u;      // RM §14.7.10, CCM_CS1CDR
constexpr uint32_t kCcmCscdr2 = 0x400FC038u;      // RM §14.7.13, CCM_CSCDR2
constexpr uint32_t kAnalogPllUsb1 = 0x400D8010u;  // RM §14.8.2, CCM_ANALOG_PLL_USB1
constexpr uint32_t kOscillatorHz = 24000000u;     // the 24 MHz crystal (RM §14.3)

bool read_word(const PeripheralBus& bus, uint32_t address, uint32_t& value) {
  BusRefusal refusal;
  return bus.read(address, 4, value, refusal);
}

// PLL3 (USB1 PLL): 20 or 22 × the crystal (DIV_SELECT bit 1), the crystal itself when bypassed
// (BYPASS bit 16, source OSC).
bool pll3_hz(const PeripheralBus& bus, uint32_t& hz) {
  uint32_t pll = 0;
  if (!read_word(bus, kAnalogPllUsb1, pll)) return false;
  if (pll & (1u << 16)) {
    hz = kOscillatorHz;
  } else {
    hz = (pll & (1u << 1)) ? 22u * kOscillatorHz : 20u * kOscillatorHz;
  }
  return true;
}

}  // namespace

bool flexio2_root_hz(const PeripheralBus& bus, uint32_t& hz) {
  uint32_t cscmr2 = 0;
  uint32_t cs1cdr = 0;
  if (!read_word(bus, kCcmCscmr2, cscmr2) || !read_word(bus, kCcmCs1cdr, cs1cdr)) return false;
  if (((cscmr2 >> 19) & 3u) != 3u) return false;  // FLEXIO2_CLK_SEL, bits 20:19: 3 = PLL3
  uint32_t source = 0;
  if (!pll3_hz(bus, source)) return false;
  const uint32_t pred = ((cs1cdr >> 9) & 7u) + 1u;   // FLEXIO2_CLK_PRED, bits 11:9
  const uint32_t podf = ((cs1cdr >> 25) & 7u) + 1u;  // FLEXIO2_CLK_PODF, bits 27:25
  hz = source / pred / podf;
  return true;
}

bool ipg_root_hz(const PeripheralBus& bus, uint32_t core_hz, uint32_t& hz) {
  uint32_t cbcdr = 0;
  if (!read_word(bus, kCcmCbcdr, cbcdr)) return false;
  hz = core_hz / (((cbcdr >> 8) & 3u) + 1u);  // IPG_PODF, bits 9:8
  return true;
}

bool lpi2c_root_hz(const PeripheralBus& bus, uint32_t& hz) {
  uint32_t cscdr2 = 0;
  if (!read_word(bus, kCcmCscdr2, cscdr2)) return false;
  const uint32_t source = (cscdr2 & (1u << 18)) ? kOscillatorHz : 480000000u / 8u;
  hz = source / (((cscdr2 >> 19) & 0x3Fu) + 1u);
  return true;
}

}  // namespace stepdance::sim::image
