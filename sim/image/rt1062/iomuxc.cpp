// IOMUXC pad registers (RM §11.7).
#include "image/rt1062/iomuxc.hpp"

#include "image/rt1062/register_bits.hpp"

namespace stepdance::sim::image::rt1062 {
namespace {

constexpr uint32_t kMuxMask = 0x1Fu;     // MUX_MODE 3:0, SION 4 (RM §11.7.1 ff.)
constexpr uint32_t kPadMask = 0x1F8F9u;  // SRE 0, DSE 5:3, SPEED 7:6, ODE 11, PKE 12, PUE 13, PUS 15:14, HYS 16
constexpr uint32_t kFirstCtl = kFirstMuxOffset + kPadCtlFromMux;  // 0x204
constexpr uint32_t kFirstSelect = 0x3F4u, kLastSelect = 0x78Cu;

// Reset values (RM §11.7): MUX_MODE ALT5 (GPIO) on every pad but the JTAG pads AD_B0_06..11
// (ALT0, JTAG); SW_PAD_CTL 0x10B0 (keeper on, 100 kΩ pull-down selected but unused, DSE R0/6,
// medium speed), the JTAG pads' own defaults aside.
bool is_jtag_pad(int pad) { return pad >= pad_index(PadBank::kAdB0, 6) && pad <= pad_index(PadBank::kAdB0, 11); }

}  // namespace

Iomuxc::Iomuxc() {
  for (int pad = 0; pad < kPadCount; ++pad) {
    mux_[static_cast<size_t>(pad)] = is_jtag_pad(pad) ? 0u : kMuxAltGpio;
    ctl_[static_cast<size_t>(pad)] = 0x10B0u;
  }
}

uint32_t Iomuxc::select_input(uint32_t offset) const {
  if (offset < kFirstSelect || offset > kLastSelect) return 0;
  return selects_[(offset - kFirstSelect) / 4u];
}

Access Iomuxc::read(uint32_t offset, uint8_t bytes, uint32_t& value) {
  const uint32_t word = offset & ~3u;
  if (word >= kFirstMuxOffset && word < kFirstCtl) {
    value = lane_read(mux_[(word - kFirstMuxOffset) / 4u], offset, bytes);
  } else if (word >= kFirstCtl && word < kFirstCtl + 4u * kPadCount) {
    value = lane_read(ctl_[(word - kFirstCtl) / 4u], offset, bytes);
  } else if (word >= kFirstSelect && word <= kLastSelect) {
    value = lane_read(selects_[(word - kFirstSelect) / 4u], offset, bytes);
  } else {
    return Access::kUnmodelled;
  }
  return Access::kOk;
}

bool Iomuxc::write_pad(uint32_t offset, uint8_t bytes, uint32_t value) {
  const uint32_t word = offset & ~3u;
  const bool is_mux = word >= kFirstMuxOffset && word < kFirstCtl;
  const bool is_ctl = word >= kFirstCtl && word < kFirstCtl + 4u * kPadCount;
  if (!is_mux && !is_ctl) return false;
  const size_t pad = (word - (is_mux ? kFirstMuxOffset : kFirstCtl)) / 4u;
  uint32_t& reg = is_mux ? mux_[pad] : ctl_[pad];
  const uint32_t old_value = reg;
  reg = lane_merge(reg, offset, bytes, value) & (is_mux ? kMuxMask : kPadMask);
  if (reg != old_value) {
    for (const auto& listener : on_pad_) listener(static_cast<int>(pad));
  }
  return true;
}

Access Iomuxc::write(uint32_t offset, uint8_t bytes, uint32_t value) {
  if (write_pad(offset, bytes, value)) return Access::kOk;
  const uint32_t word = offset & ~3u;
  if (word < kFirstSelect || word > kLastSelect) return Access::kUnmodelled;
  uint32_t& reg = selects_[(word - kFirstSelect) / 4u];
  reg = lane_merge(reg, offset, bytes, value);
  return Access::kOk;
}

}  // namespace stepdance::sim::image::rt1062
