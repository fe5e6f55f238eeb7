// IOMUXC_GPR (RM §11.4).
#include "image/rt1062/iomuxc_gpr.hpp"

#include "image/rt1062/register_bits.hpp"

namespace stepdance::sim::image::rt1062 {

IomuxcGpr::IomuxcGpr() { values_[16] = 0x00200003u; }

Access IomuxcGpr::read(uint32_t offset, uint8_t bytes, uint32_t& value) {
  if (offset / 4u >= kCount) return Access::kUnmodelled;
  value = lane_read(values_[offset / 4u], offset, bytes);
  return Access::kOk;
}

Access IomuxcGpr::write(uint32_t offset, uint8_t bytes, uint32_t value) {
  const unsigned index = offset / 4u;
  if (index >= kCount) return Access::kUnmodelled;
  values_[index] = lane_merge(values_[index], offset, bytes, value);
  for (const auto& listener : on_change_) listener(index);
  return Access::kOk;
}

}  // namespace stepdance::sim::image::rt1062
