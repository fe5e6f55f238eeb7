// The RT1062's GPIO pads: their IOMUXC registers and the GPIO port bit each one carries.
// Facts from the reference manual: pad order and SW_MUX_CTL offsets (RM §11.7, IOMUXC memory
// map), pad → GPIO1..5 bits (RM §12.2 / table 10-1 "muxing options", ALT5 = GPIOn_IOmm), and the
// ADC inputs on the AD_B pads (RM §66, "ADC external signals" and table 10-1 ALT "ADCx_INn").
#pragma once

#include <cstdint>

namespace stepdance::sim::image::rt1062 {

/// Pads by index 0..123 in IOMUXC order: EMC_00..41, AD_B0_00..15, AD_B1_00..15, B0_00..15,
/// B1_00..15, SD_B0_00..05, SD_B1_00..11. SW_MUX_CTL_PAD is at 0x014 + 4 × index, SW_PAD_CTL_PAD
/// 0x1F0 above it (RM §11.7).
constexpr int kPadCount = 124;
constexpr uint32_t kFirstMuxOffset = 0x014u;
constexpr uint32_t kPadCtlFromMux = 0x1F0u;

enum class PadBank : uint8_t { kEmc, kAdB0, kAdB1, kB0, kB1, kSdB0, kSdB1 };

/// The index of pad `n` of `bank` (EMC 0..41, SD_B0 0..5, SD_B1 0..11, others 0..15), or -1.
int pad_index(PadBank bank, int n);
/// The SW_MUX_CTL_PAD offset of a pad (from the IOMUXC base).
constexpr uint32_t pad_mux_offset(int pad) { return kFirstMuxOffset + 4u * static_cast<uint32_t>(pad); }
/// The pad whose SW_MUX_CTL_PAD is at `offset`, or -1.
int pad_from_mux_offset(uint32_t offset);

/// A standard GPIO port (1..5) and bit.
struct GpioBit {
  uint8_t port = 0;  ///< 1..4 for these pads (GPIO5 is on the SNVS pads); 0 = none
  uint8_t bit = 0;
};
/// The GPIO port bit a pad carries in ALT5 (RM table 10-1): EMC_00..31 = GPIO4 0..31,
/// EMC_32..41 = GPIO3 18..27, AD_B0 = GPIO1 0..15, AD_B1 = GPIO1 16..31, B0 = GPIO2 0..15,
/// B1 = GPIO2 16..31, SD_B0 = GPIO3 12..17, SD_B1 = GPIO3 0..11.
GpioBit pad_gpio(int pad);
/// The pad carrying GPIO `port` (1..4, or the fast aliases 6..9) bit `bit`, or -1.
int gpio_pad(unsigned port, unsigned bit);

/// The pad on input channel `channel` (0..15) of ADC `module` (0 = ADC1, 1 = ADC2), or -1.
/// ADC1: IN0 = AD_B1_11, IN1..4 = AD_B0_12..15, IN5..15 = AD_B1_00..10. ADC2: IN0 = AD_B1_11,
/// IN1..4 = AD_B1_12..15, IN5..15 = AD_B1_00..10.
int adc_input_pad(unsigned module, unsigned channel);

/// The pad's name, e.g. "GPIO_B0_03" (static storage).
const char* pad_name(int pad);

}  // namespace stepdance::sim::image::rt1062
