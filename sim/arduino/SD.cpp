// SD and File on the host, over hal::storage().
#include "SD.h"

#include <string.h>

#include "stepdance/hal/storage.hpp"

namespace {

using stepdance::FileMode;
using stepdance::Status;

stepdance::FileStorage& storage() { return stepdance::hal::storage(); }

}  // namespace

SDClass SD;

File::File(int handle, const char* name, bool writable) : handle_(handle), writable_(writable) {
  strncpy(name_, name, sizeof(name_) - 1);
}

bool File::fill() {
  if (handle_ < 0) return false;
  if (next_ < buffered_) return true;
  size_t read = 0;
  if (storage().read(handle_, buffer_, sizeof(buffer_), read) != Status::kOk) read = 0;
  buffered_ = read;
  next_ = 0;
  return read > 0;
}

int File::available() { return fill() ? static_cast<int>(buffered_ - next_) : 0; }

int File::read() { return fill() ? buffer_[next_++] : -1; }

int File::peek() { return fill() ? buffer_[next_] : -1; }

int File::read(void* buffer, size_t length) {
  auto* out = static_cast<uint8_t*>(buffer);
  size_t count = 0;
  while (count < length && fill()) {
    const size_t chunk = (buffered_ - next_) < (length - count) ? (buffered_ - next_) : (length - count);
    memcpy(out + count, buffer_ + next_, chunk);
    next_ += chunk;
    count += chunk;
  }
  return static_cast<int>(count);
}

size_t File::write(uint8_t byte) { return write(&byte, 1); }

size_t File::write(const uint8_t* data, size_t length) {
  if (handle_ < 0 || !writable_ || length == 0) return 0;
  return storage().write(handle_, data, length) == Status::kOk ? length : 0;
}

void File::close() {
  if (handle_ >= 0) storage().close(handle_);
  handle_ = -1;
  name_[0] = '\0';
  buffered_ = next_ = 0;
}

bool SDClass::begin(uint8_t) {
  // An invalid name tells "no storage" (kUnsupported) apart from "storage" (kBadArgument).
  int handle = -1;
  const Status status = storage().open("", FileMode::kRead, handle);
  if (status == Status::kOk) storage().close(handle);
  return status != Status::kUnsupported;
}

File SDClass::open(const char* path, uint8_t mode) {
  if (path == nullptr || mode > FILE_WRITE_BEGIN) return File();
  const FileMode file_mode = mode == FILE_READ    ? FileMode::kRead
                             : mode == FILE_WRITE ? FileMode::kAppend
                                                  : FileMode::kWriteTruncate;
  int handle = -1;
  if (storage().open(path, file_mode, handle) != Status::kOk) return File();
  return File(handle, path, mode != FILE_READ);
}

bool SDClass::exists(const char* path) {
  File file = open(path, FILE_READ);
  const bool found = static_cast<bool>(file);
  file.close();
  return found;
}

bool SDClass::remove(const char*) { return false; }
