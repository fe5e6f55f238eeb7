// The analog register window shared by CCM_ANALOG, PMU, TEMPMON and the other analog blocks.
#include "image/rt1062/analog_window.hpp"

namespace stepdance::sim::image::rt1062 {

WindowPart* AnalogWindow::part_at(uint32_t offset) const {
  for (WindowPart* part : parts_) {
    if (part->covers(offset)) return part;
  }
  return nullptr;
}

Access AnalogWindow::read(uint32_t offset, uint8_t bytes, uint32_t& value) {
  WindowPart* part = part_at(offset);
  return part == nullptr ? Access::kUnmodelled : part->read(offset, bytes, value);
}

Access AnalogWindow::write(uint32_t offset, uint8_t bytes, uint32_t value) {
  WindowPart* part = part_at(offset);
  return part == nullptr ? Access::kUnmodelled : part->write(offset, bytes, value);
}

}  // namespace stepdance::sim::image::rt1062
