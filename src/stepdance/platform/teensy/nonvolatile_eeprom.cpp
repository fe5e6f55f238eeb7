// nonvolatile_store(): the Teensy 4.x's EEPROM emulation (a wear-levelled area of its program
// flash, through Teensyduino's EEPROM routines). Loop context only; a write programs flash with
// interrupts off, so callers write only while no motion runs.
#if defined(__IMXRT1062__)

#include "stepdance/hal/nonvolatile.hpp"
#include "stepdance/platform/teensy/teensyduino_services.hpp"

namespace stepdance::platform::teensy {
namespace {

class EepromStore final : public NonvolatileStore {
 public:
  size_t size_bytes() override { return services::eeprom_bytes(); }

  Status read(size_t offset, uint8_t* data, size_t length) override {
    if (!fits(offset, length)) return Status::kBadArgument;
    services::eeprom_read(offset, data, length);
    return Status::kOk;
  }

  Status write(size_t offset, const uint8_t* data, size_t length) override {
    if (!fits(offset, length)) return Status::kBadArgument;
    services::eeprom_write(offset, data, length);
    return Status::kOk;
  }

 private:
  bool fits(size_t offset, size_t length) { return offset <= size_bytes() && length <= size_bytes() - offset; }
};

EepromStore eeprom_store;

}  // namespace
}  // namespace stepdance::platform::teensy

namespace stepdance::hal {
NonvolatileStore& nonvolatile_store() { return platform::teensy::eeprom_store; }
}  // namespace stepdance::hal

#endif  // __IMXRT1062__
