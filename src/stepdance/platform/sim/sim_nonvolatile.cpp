// Inside a board's shared object: the non-volatile store, kept as one file of the board's storage
// folder (`<output>/<board>.sd/eeprom.bin`), so it survives a re-run into the same output folder
// as a Teensy's EEPROM survives a reset. The size is a Teensy 4.0's (the smaller of the two).
#if defined(STEPDANCE_PLATFORM_SIM)

#include <string.h>

#include "stepdance/hal/nonvolatile.hpp"
#include "stepdance/hal/storage.hpp"
#include "stepdance/platform/sim/host_link.hpp"

namespace stepdance {
namespace {

constexpr size_t kStoreBytes = 1080;
constexpr const char* kStoreFile = "eeprom.bin";

/// The whole image is read on first use and rewritten on every write (a write is rare: a
/// settings change). Without a storage folder it still works, but only for this run.
class SimulatedEeprom final : public NonvolatileStore {
 public:
  size_t size_bytes() override { return kStoreBytes; }

  Status read(size_t offset, uint8_t* data, size_t length) override {
    if (!fits(offset, length)) return Status::kBadArgument;
    load();
    memcpy(data, image_ + offset, length);
    return Status::kOk;
  }

  Status write(size_t offset, const uint8_t* data, size_t length) override {
    if (!fits(offset, length)) return Status::kBadArgument;
    load();
    memcpy(image_ + offset, data, length);
    return save();
  }

 private:
  static bool fits(size_t offset, size_t length) { return offset <= kStoreBytes && length <= kStoreBytes - offset; }

  void load() {
    if (loaded_) return;
    loaded_ = true;
    memset(image_, 0xFF, sizeof(image_));  // erased flash
    FileStorage& storage = hal::storage();
    int handle = -1;
    if (storage.open(kStoreFile, FileMode::kRead, handle) != Status::kOk) return;
    size_t total = 0;
    size_t got = 0;
    while (total < kStoreBytes && storage.read(handle, image_ + total, kStoreBytes - total, got) == Status::kOk &&
           got > 0) {
      total += got;
    }
    storage.close(handle);
  }

  Status save() {
    FileStorage& storage = hal::storage();
    int handle = -1;
    const Status opened = storage.open(kStoreFile, FileMode::kWriteTruncate, handle);
    if (opened == Status::kUnsupported) return Status::kOk;  // no folder: this run only
    if (opened != Status::kOk) return Status::kIoError;
    const Status written = storage.write(handle, image_, kStoreBytes);
    const Status closed = storage.close(handle);
    return written != Status::kOk ? written : closed;
  }

  uint8_t image_[kStoreBytes] = {};
  bool loaded_ = false;
};

SimulatedEeprom the_eeprom;

}  // namespace

namespace hal {
NonvolatileStore& nonvolatile_store() { return the_eeprom; }
}  // namespace hal

}  // namespace stepdance

#endif  // STEPDANCE_PLATFORM_SIM
