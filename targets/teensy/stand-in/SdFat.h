// Stand-in declarations of SdFat as Teensyduino 1.59 bundles it (libraries/SdFat), as far as the
// Teensy backend uses it (the list is in src/stepdance/platform/teensy/teensyduino_storage.hpp),
// plus SdFs, which the heap probe (targets/teensy/heap-probe/sdfs_probe.cpp) uses. Like the real
// library, the volume and file objects keep their state inside themselves: nothing here allocates.
// The definitions in SdFat.cpp behave as if no card were inserted.
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

// The card classes, shaped as SdFat 2.x shapes them: the block-device base has a virtual
// destructor, so GCC gives each card class a deleting destructor in its vtable, and that calls
// the global operator delete. The vtables are emitted in SdFat.cpp (each class's first non-inline
// virtual function is there, as in SdioTeensy.cpp and SdSpiCard.cpp), so an image that builds one
// of these cards names operator delete although nothing is ever deleted: the reference that pulls
// the core's operator delete (new.cpp) and its heap in. The backend's card (SdCardBuiltin in
// teensyduino_storage.hpp) has an operator delete of its own for that reason.

/// A block device (SdFat's FsBlockDeviceInterface).
class FsBlockDeviceInterface {
 public:
  virtual ~FsBlockDeviceInterface() {}
  virtual bool isBusy() = 0;
};

typedef FsBlockDeviceInterface FsBlockDevice;

/// A card (SdFat's SdCardInterface).
class SdCardInterface : public FsBlockDeviceInterface {
 public:
  virtual uint8_t errorCode() const = 0;
};

/// The built-in slot's card, on SDIO.
class SdioCard : public SdCardInterface {
 public:
  bool begin(SdioConfig config);
  bool isBusy() override;
  uint8_t errorCode() const override;
};

/// A card on a SPI bus of its own.
class DedicatedSpiCard : public SdCardInterface {
 public:
  bool isBusy() override;
  uint8_t errorCode() const override;
};

/// A FAT or exFAT volume.
class FsVolume {
 public:
  /// Mounts the device's first partition.
  bool begin(FsBlockDevice* device);
  bool remove(const char* path);

 protected:
  bool mounted_ = false;
};

/// Holds one card of each kind by value and hands out the one asked for (SdFat's SdCardFactory).
class SdCardFactory {
 public:
  SdCardInterface* newCard(SdioConfig config) { return sdio_card_.begin(config) ? &sdio_card_ : nullptr; }

 private:
  SdioCard sdio_card_;
  DedicatedSpiCard spi_card_;
};

/// The SD card and its volume (SdFat's SdBase<FsVolume, ...>): the card factory holds one card of
/// each kind by value.
class SdFs : public FsVolume {
 public:
  bool begin(SdioConfig config);

 private:
  SdCardFactory card_factory_;
  SdCardInterface* card_ = nullptr;
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
