// TEMPMON (RM §16.5).
#include "image/rt1062/tempmon.hpp"

#include "image/rt1062/register_bits.hpp"

namespace stepdance::sim::image::rt1062 {
namespace {

constexpr uint32_t kOffsets[3] = {0x180, 0x190, 0x290};  // TEMPSENSE0, 1, 2 (window offsets)
constexpr uint32_t kPowerDown = 1u << 0, kMeasure = 1u << 1, kFinished = 1u << 2;
constexpr uint32_t kTempCountMask = 0xFFFu << 8;

}  // namespace

Tempmon::Tempmon(uint32_t ana1_fuse) : room_count_(ana1_fuse >> 20) {}

int Tempmon::index(uint32_t offset) const {
  for (int i = 0; i < 3; ++i) {
    if (offset >= kOffsets[i] && offset < kOffsets[i] + 16u) return i;
  }
  return -1;
}

bool Tempmon::covers(uint32_t offset) const { return index(offset) >= 0; }

uint32_t Tempmon::sense0() const {
  const uint32_t value = values_[0] & ~(kFinished | kTempCountMask);
  if ((value & kPowerDown) || !(value & kMeasure)) return value;
  return value | kFinished | (room_count_ << 8);
}

Access Tempmon::read(uint32_t offset, uint8_t bytes, uint32_t& value) {
  const int i = index(offset);
  if (i < 0) return Access::kUnmodelled;
  value = lane_read(i == 0 ? sense0() : values_[static_cast<size_t>(i)], offset, bytes);
  return Access::kOk;
}

Access Tempmon::write(uint32_t offset, uint8_t bytes, uint32_t value) {
  const int i = index(offset);
  if (i < 0) return Access::kUnmodelled;
  uint32_t& reg = values_[static_cast<size_t>(i)];
  const auto alias = static_cast<Alias>(((offset & ~3u) - kOffsets[i]) / 4u);
  reg = apply_alias(reg, alias, lane_merge(alias == Alias::kWrite ? reg : 0u, offset, bytes, value));
  if (i == 0) reg &= ~(kFinished | kTempCountMask);  // read only
  return Access::kOk;
}

}  // namespace stepdance::sim::image::rt1062
