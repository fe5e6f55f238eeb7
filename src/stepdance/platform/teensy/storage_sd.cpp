// storage(): FileStorage on the Teensy 4.1's built-in SD slot through SdFat; on a Teensy 4.0,
// which has no slot (its core still defines BUILTIN_SDCARD), a storage that refuses every file.
//
// No heap: the card volume and up to four open files are built in place in this file's static
// storage, the volume on the first open(), each file while it is open. Nothing here runs before
// then and the object below is constant-initialised, so a sketch that never calls hal::storage()
// (only the recorder and player do) links none of it: the linker drops it with SdFat.
// Context: loop only; card operations may block for milliseconds.
#if defined(__IMXRT1062__)

#include <string.h>
#include <new>

#include "stepdance/core/byte_stream.hpp"
#include "stepdance/hal/storage.hpp"
#include "stepdance/platform/teensy/teensyduino_storage.hpp"

namespace stepdance::platform::teensy {
namespace {

#if defined(ARDUINO_TEENSY40)

class NoCardSlot final : public FileStorage {
 public:
  Status open(const char*, FileMode, int&) override { return Status::kUnsupported; }
  Status read(int, uint8_t*, size_t, size_t&) override { return Status::kBadArgument; }
  Status write(int, const uint8_t*, size_t) override { return Status::kBadArgument; }
  Status close(int) override { return Status::kBadArgument; }
};

NoCardSlot the_storage;

#else

// Ends the life of an object built in place (the storage bytes stay for the next one).
template <typename T>
void destroy(T* object) {
  object->~T();
}

bool valid_name(const char* name) {
  return name != nullptr && name[0] != '\0' && strlen(name) <= FileStorage::kMaxNameLength;
}

class SdStorage final : public FileStorage {
 public:
  Status open(const char* name, FileMode mode, int& handle) override {
    if (!valid_name(name)) return Status::kBadArgument;
    if (!card_ready()) return Status::kIoError;  // no card inserted, or it does not answer
    int slot = 0;
    while (slot < kMaxOpenFiles && files_[slot] != nullptr) ++slot;
    if (slot == kMaxOpenFiles) return Status::kFull;
    services::SdFile* file = new (file_bytes_[slot]) services::SdFile;
    if (!open_file(*file, name, mode)) {
      destroy(file);
      return Status::kIoError;
    }
    files_[slot] = file;
    handle = slot;
    return Status::kOk;
  }

  Status read(int handle, uint8_t* data, size_t length, size_t& read) override {
    if (!valid(handle)) return Status::kBadArgument;
    const int count = services::sd_read(*files_[handle], data, length);
    if (count < 0) return Status::kIoError;
    read = static_cast<size_t>(count);
    return Status::kOk;
  }

  Status write(int handle, const uint8_t* data, size_t length) override {
    if (!valid(handle)) return Status::kBadArgument;
    return services::sd_write(*files_[handle], data, length) == length ? Status::kOk : Status::kIoError;
  }

  Status close(int handle) override {
    if (!valid(handle)) return Status::kBadArgument;
    const bool flushed = services::sd_close(*files_[handle]);
    destroy(files_[handle]);
    files_[handle] = nullptr;
    return flushed ? Status::kOk : Status::kIoError;
  }

 private:
  static constexpr int kMaxOpenFiles = 4;

  bool open_file(services::SdFile& file, const char* name, FileMode mode) {
    switch (mode) {
      case FileMode::kRead: return services::sd_open_read(*volume_, file, name);
      case FileMode::kWriteTruncate: return services::sd_open_truncate(*volume_, file, name);
      case FileMode::kAppend: return services::sd_open_append(*volume_, file, name);
    }
    return false;
  }

  // Builds the volume on first use and starts the card; tries again later if none was inserted.
  bool card_ready() {
    if (volume_ == nullptr) volume_ = new (volume_bytes_) services::SdVolume;
    if (!card_started_) card_started_ = services::sd_begin_builtin(*volume_);
    return card_started_;
  }
  bool valid(int handle) const { return handle >= 0 && handle < kMaxOpenFiles && files_[handle] != nullptr; }

  alignas(services::SdVolume) unsigned char volume_bytes_[sizeof(services::SdVolume)] = {};
  alignas(services::SdFile) unsigned char file_bytes_[kMaxOpenFiles][sizeof(services::SdFile)] = {};
  services::SdVolume* volume_ = nullptr;
  services::SdFile* files_[kMaxOpenFiles] = {};
  bool card_started_ = false;
};

SdStorage the_storage;

#endif  // ARDUINO_TEENSY40

}  // namespace
}  // namespace stepdance::platform::teensy

namespace stepdance::hal {
FileStorage& storage() { return platform::teensy::the_storage; }
}  // namespace stepdance::hal

#endif  // __IMXRT1062__
