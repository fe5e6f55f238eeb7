// storage(): FileStorage on the Teensy 4.1's built-in SD slot through the Teensy SD library.
// Loop context only; SD operations may block for milliseconds.
#if defined(__IMXRT1062__)

#include <string.h>

#include "stepdance/core/byte_stream.hpp"  // file_storage.hpp names ByteStream without including it
#include "stepdance/core/file_storage.hpp"
#include "stepdance/platform/teensy/teensyduino_services.hpp"

namespace stepdance::platform::teensy {
namespace {

class SdStorage final : public FileStorage {
 public:
  Status open(const char* name, FileMode mode, int& handle) override {
    if (name == nullptr || strlen(name) == 0 || strlen(name) > kMaxNameLength) return Status::kBadArgument;
    if (!card_ready()) return Status::kUnsupported;
    int slot = 0;
    while (slot < kMaxOpenFiles && files_[slot]) ++slot;
    if (slot == kMaxOpenFiles) return Status::kFull;
    if (mode == FileMode::kWriteTruncate) services::sd_remove(name);  // FILE_WRITE then starts empty
    files_[slot] = mode == FileMode::kRead ? services::sd_open_read(name) : services::sd_open_append(name);
    if (!files_[slot]) return Status::kIoError;
    handle = slot;
    return Status::kOk;
  }

  Status read(int handle, uint8_t* data, size_t length, size_t& read) override {
    if (!valid(handle)) return Status::kBadArgument;
    const size_t count = files_[handle].read(data, length);
    if (count > length) return Status::kIoError;  // the library's -1, seen through size_t
    read = count;
    return Status::kOk;
  }

  Status write(int handle, const uint8_t* data, size_t length) override {
    if (!valid(handle)) return Status::kBadArgument;
    return files_[handle].write(data, length) == length ? Status::kOk : Status::kIoError;
  }

  Status close(int handle) override {
    if (!valid(handle)) return Status::kBadArgument;
    files_[handle].close();
    files_[handle] = services::SdFileHandle();
    return Status::kOk;
  }

 private:
  static constexpr int kMaxOpenFiles = 4;

  // Starts the card on first use; tries again later if no card was inserted.
  bool card_ready() {
    if (!card_started_) card_started_ = services::sd_begin_builtin();
    return card_started_;
  }
  bool valid(int handle) { return handle >= 0 && handle < kMaxOpenFiles && files_[handle]; }

  services::SdFileHandle files_[kMaxOpenFiles];
  bool card_started_ = false;
};

SdStorage sd_storage;

}  // namespace
}  // namespace stepdance::platform::teensy

namespace stepdance::hal {
FileStorage& storage() { return platform::teensy::sd_storage; }
}  // namespace stepdance::hal

#endif  // __IMXRT1062__
