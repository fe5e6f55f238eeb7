// Stand-in declarations of SdFat as Teensyduino 1.59 bundles it (libraries/SdFat), as far as the
// Teensy backend uses it (the list is in src/stepdance/platform/teensy/teensyduino_storage.hpp).
// Like the real library, the volume and file objects keep their state inside themselves: nothing
// here allocates. The definitions in SdFat.cpp behave as if no card were inserted.
#pragma once

#include <stddef.h>
#include <stdint.h>

#define FIFO_SDIO 0

// Open flags, with the values of SdFat's own FsApiConstants.h (USE_FCNTL_H off).
#define O_RDONLY 0x00
#define O_WRONLY 0x01
#define O_RDWR 0x02
#define O_AT_END 0x04
#define O_APPEND 0x08
#define O_CREAT 0x10
#define O_TRUNC 0x20
typedef uint8_t oflag_t;

/// How the built-in slot's SDIO interface runs.
class SdioConfig {
 public:
  explicit SdioConfig(uint8_t options) : options_(options) {}
  uint8_t options() const { return options_; }

 private:
  uint8_t options_;
};

/// A FAT or exFAT volume.
class FsVolume {
 public:
  bool remove(const char* path);

 protected:
  bool mounted_ = false;
};

/// The SD card and its volume.
class SdFs : public FsVolume {
 public:
  bool begin(SdioConfig config);
};

/// A file on a volume; closed when destroyed.
class FsFile {
 public:
  FsFile() = default;
  FsFile(const FsFile&) = delete;
  FsFile& operator=(const FsFile&) = delete;
  ~FsFile() { close(); }

  bool open(FsVolume* volume, const char* path, oflag_t flags);
  int read(void* buffer, size_t count);
  size_t write(const void* buffer, size_t count);
  bool close();
  bool isOpen() const { return open_; }

 private:
  bool open_ = false;
};
