// OCOTP fuse shadows (RM §23.6).
#include "image/rt1062/ocotp.hpp"

#include "image/rt1062/register_bits.hpp"

namespace stepdance::sim::image::rt1062 {
namespace {

// The modelled shadows (RM §23.6.1): LOCK 0x400, CFG0..6 0x410..0x470, ANA0..2 0x4D0..0x4F0,
// MAC0/1 0x620/0x630.
constexpr uint32_t kShadows[12] = {0x400, 0x410, 0x420, 0x430, 0x440, 0x450, 0x460, 0x470, 0x4D0, 0x4E0, 0x4F0, 0x620};
constexpr uint32_t kMac1 = 0x630;

}  // namespace

Ocotp::Ocotp() {
  fuses_[9] = kAna1;
  fuses_[11] = 0x00123456u;  // MAC0: serial 1193046 (Teensyduino's USB serial uses the low 24 bits)
}

int Ocotp::index(uint32_t offset) const {
  const uint32_t word = offset & ~3u;
  for (int i = 0; i < 12; ++i) {
    if (kShadows[i] == word) return i;
  }
  return word == kMac1 ? 12 : -1;
}

Access Ocotp::read(uint32_t offset, uint8_t bytes, uint32_t& value) {
  const int i = index(offset);
  if (i < 0) return Access::kUnmodelled;
  value = lane_read(i == 12 ? 0u : fuses_[static_cast<size_t>(i)], offset, bytes);
  return Access::kOk;
}

Access Ocotp::write(uint32_t offset, uint8_t, uint32_t) {
  return index(offset) < 0 ? Access::kUnmodelled : Access::kOk;  // shadows of fuses: writes ignored
}

bool Ocotp::set_fuse(uint32_t offset, uint32_t value) {
  const int i = index(offset);
  if (i < 0 || i == 12) return false;
  fuses_[static_cast<size_t>(i)] = value;
  return true;
}

}  // namespace stepdance::sim::image::rt1062
