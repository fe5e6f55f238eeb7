// The analog register window at 0x400D8000 (RM §2.2, memory map table 2-2: one 4 KB slot holds
// CCM_ANALOG, PMU, TEMPMON, USB_ANALOG and XTALOSC24M, their registers interleaved by offset).
#pragma once

#include <cstdint>
#include <vector>

#include "image/chip/peripheral.hpp"

namespace stepdance::sim::image::rt1062 {

/// One block's registers inside the analog window. Offsets are from the window's base.
class WindowPart {
 public:
  virtual ~WindowPart() = default;
  /// The reference manual's name of the block, e.g. "TEMPMON".
  virtual const char* part_name() const = 0;
  /// True if the register (or alias) at `offset` belongs to this block.
  virtual bool covers(uint32_t offset) const = 0;
  virtual Access read(uint32_t offset, uint8_t bytes, uint32_t& value) = 0;
  virtual Access write(uint32_t offset, uint8_t bytes, uint32_t value) = 0;
};

/// The shared window as one Peripheral: an access goes to the part that covers its offset;
/// an offset no part covers is unmodelled. Other helpers add their parts (USB_ANALOG) by
/// registration, before the image runs. Always clocked (no CCGR gate).
class AnalogWindow : public Peripheral {
 public:
  static constexpr uint32_t kBase = 0x400D8000u;  // RM table 2-2, CCM_ANALOG slot
  static constexpr uint32_t kSize = 0x1000u;      // 4 KB; USBPHY1 begins at 0x400D9000

  const char* name() const override { return "CCM_ANALOG"; }
  uint32_t base() const override { return kBase; }
  uint32_t size_bytes() const override { return kSize; }
  /// Adds a part. The window does not own it; parts must not cover the same offsets.
  void add(WindowPart& part) { parts_.push_back(&part); }
  /// The part covering `offset`, or null.
  WindowPart* part_at(uint32_t offset) const;
  Access read(uint32_t offset, uint8_t bytes, uint32_t& value) override;
  Access write(uint32_t offset, uint8_t bytes, uint32_t value) override;

 private:
  std::vector<WindowPart*> parts_;
};

}  // namespace stepdance::sim::image::rt1062
