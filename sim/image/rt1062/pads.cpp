// Pad facts of the RT1062 (RM §11.7, table 10-1).
#include "image/rt1062/pads.hpp"

#include <array>
#include <cstdio>
#include <string>

namespace stepdance::sim::image::rt1062 {
namespace {

struct Bank {
  const char* name;
  int first_pad;
  int count;
};
// In IOMUXC register order (RM §11.7).
constexpr Bank kBanks[] = {{"EMC", 0, 42}, {"AD_B0", 42, 16}, {"AD_B1", 58, 16}, {"B0", 74, 16},
                           {"B1", 90, 16}, {"SD_B0", 106, 6}, {"SD_B1", 112, 12}};

const Bank& bank_of(int pad) {
  for (const Bank& bank : kBanks) {
    if (pad >= bank.first_pad && pad < bank.first_pad + bank.count) return bank;
  }
  return kBanks[0];
}

}  // namespace

int pad_index(PadBank bank, int n) {
  const Bank& b = kBanks[static_cast<size_t>(bank)];
  return n >= 0 && n < b.count ? b.first_pad + n : -1;
}

int pad_from_mux_offset(uint32_t offset) {
  if (offset < kFirstMuxOffset || (offset & 3u) != 0) return -1;
  const int pad = static_cast<int>((offset - kFirstMuxOffset) / 4u);
  return pad < kPadCount ? pad : -1;
}

GpioBit pad_gpio(int pad) {
  if (pad < 0 || pad >= kPadCount) return {};
  const Bank& bank = bank_of(pad);
  const int n = pad - bank.first_pad;
  const auto bit = [](int value) { return static_cast<uint8_t>(value); };
  switch (bank.first_pad) {
    case 0: return n < 32 ? GpioBit{4, bit(n)} : GpioBit{3, bit(n - 32 + 18)};
    case 42: return {1, bit(n)};
    case 58: return {1, bit(16 + n)};
    case 74: return {2, bit(n)};
    case 90: return {2, bit(16 + n)};
    case 106: return {3, bit(12 + n)};
    default: return {3, bit(n)};
  }
}

int gpio_pad(unsigned port, unsigned bit) {
  if (port >= 6 && port <= 9) port -= 5;  // GPIO6..9 are the fast twins of GPIO1..4 (RM §12.1)
  if (port < 1 || port > 4 || bit > 31) return -1;
  for (int pad = 0; pad < kPadCount; ++pad) {
    const GpioBit gpio = pad_gpio(pad);
    if (gpio.port == port && gpio.bit == bit) return pad;
  }
  return -1;
}

int adc_input_pad(unsigned module, unsigned channel) {
  if (module > 1 || channel > 15) return -1;
  const int n = static_cast<int>(channel);
  if (channel == 0) return pad_index(PadBank::kAdB1, 11);
  if (channel >= 5) return pad_index(PadBank::kAdB1, n - 5);
  return module == 0 ? pad_index(PadBank::kAdB0, 11 + n) : pad_index(PadBank::kAdB1, 11 + n);
}

const char* pad_name(int pad) {
  static const std::array<std::string, kPadCount> names = [] {
    std::array<std::string, kPadCount> all;
    for (const Bank& bank : kBanks) {
      for (int n = 0; n < bank.count; ++n) {
        char text[24];
        std::snprintf(text, sizeof text, "GPIO_%s_%02d", bank.name, n);
        all[static_cast<size_t>(bank.first_pad + n)] = text;
      }
    }
    return all;
  }();
  return pad >= 0 && pad < kPadCount ? names[static_cast<size_t>(pad)].c_str() : "?";
}

}  // namespace stepdance::sim::image::rt1062
