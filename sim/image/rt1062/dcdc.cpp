// DCDC and PMU regulator registers.
#include "image/rt1062/dcdc.hpp"

#include "image/rt1062/register_bits.hpp"

namespace stepdance::sim::image::rt1062 {
namespace {

constexpr uint32_t kStsDcOk = 1u << 31;  // DCDC_REG0 STS_DC_OK (RM §18.6.1), read only

}  // namespace

// Reset values: RM §18.6.1–18.6.4 (REG0..REG3).
Dcdc::Dcdc() : values_{0x14030111u, 0x111BA29Cu, 0x00004009u, 0x0000010Eu} {}

Access Dcdc::read(uint32_t offset, uint8_t bytes, uint32_t& value) {
  if (offset >= 16u) return Access::kUnmodelled;
  uint32_t word = values_[offset / 4u];
  if (offset < 4u) word |= kStsDcOk;
  value = lane_read(word, offset, bytes);
  return Access::kOk;
}

Access Dcdc::write(uint32_t offset, uint8_t bytes, uint32_t value) {
  if (offset >= 16u) return Access::kUnmodelled;
  uint32_t& reg = values_[offset / 4u];
  reg = lane_merge(reg, offset, bytes, value);
  if (offset < 4u) reg &= ~kStsDcOk;
  return Access::kOk;
}

// Reset values: RM §13.4.1–13.4.4 (PMU_REG_1P1, REG_3P0, REG_2P5, REG_CORE).
Pmu::Pmu() : values_{0x00001073u, 0x00000F74u, 0x00001073u, 0x00482012u} {}

Access Pmu::read(uint32_t offset, uint8_t bytes, uint32_t& value) {
  if (!covers(offset)) return Access::kUnmodelled;
  value = lane_read(values_[(offset - 0x110u) / 16u], offset, bytes);
  return Access::kOk;
}

Access Pmu::write(uint32_t offset, uint8_t bytes, uint32_t value) {
  if (!covers(offset)) return Access::kUnmodelled;
  uint32_t& reg = values_[(offset - 0x110u) / 16u];
  const auto alias = static_cast<Alias>((offset & 0xCu) / 4u);
  reg = apply_alias(reg, alias, lane_merge(alias == Alias::kWrite ? reg : 0u, offset, bytes, value));
  return Access::kOk;
}

}  // namespace stepdance::sim::image::rt1062
