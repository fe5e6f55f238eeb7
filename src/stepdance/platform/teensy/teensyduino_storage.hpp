// The ONLY door from the Teensy backend to SdFat, the card library Teensyduino bundles
// (libraries/SdFat, Bill Greiman's SdFat 2.x). Only storage_sd.cpp includes it.
//
// Why SdFat and not Teensyduino's SD library: SD's open() allocates every File on the heap and
// frees it from the File's destructor. SdFat's volume and file objects keep their state inside
// themselves, so ours live in static storage and are built in place on first use.
//
// Why not SdFat's SdFs (card and volume in one object): SdFs holds one card object of each kind
// (SdioCard, DedicatedSpiCard). Their base class, FsBlockDeviceInterface, has a virtual destructor,
// so each card's vtable holds a "deleting destructor", and that calls the global operator delete:
// the core's (cores/teensy4/new.cpp), on free(). Nothing is ever deleted, but building an SdFs
// names those vtables, and the image then links malloc, free and _sbrk. So we pair an FsVolume
// with a card of our own type, SdCardBuiltin: SdFat's SdioCard with a class-specific operator
// delete, which its deleting destructor calls instead of the global one. Built in place at -O1 and
// above (every Optimize setting but Debug), the compiler drops the base classes' vtable stores
// and nothing names SdFat's own card vtables (scripts/build-teensy.sh checks the images; with
// Debug, -Og, the heap code is linked again, though never called). A library-provided global
// operator delete cannot do this: the IDE links SPI (SdFat includes it), whose use of `new` pulls
// the core's new.cpp, and with it the core's operator delete, into every image.
//
// The CI stand-in (targets/teensy/stand-in/SdFat.h) declares exactly these, with these signatures:
//
//   <SdFat.h>
//     #define FIFO_SDIO                                 // the built-in slot's SDIO mode
//     #define O_RDONLY, O_WRONLY, O_CREAT, O_TRUNC, O_AT_END   // open flags, of type oflag_t
//     class SdioConfig { explicit SdioConfig(uint8_t options); };
//     class FsBlockDeviceInterface { virtual ~FsBlockDeviceInterface(); ... };
//     typedef FsBlockDeviceInterface FsBlockDevice;
//     class SdioCard : public SdCardInterface {      // SdCardInterface : FsBlockDeviceInterface
//       SdioCard();  bool begin(SdioConfig config);     // false: no card, or it does not answer
//       uint8_t errorCode() const;                      // 0: no error
//     };
//     class FsVolume {                                  // a FAT or exFAT volume
//       FsVolume();  bool begin(FsBlockDevice* device); // mounts the card's first partition
//       bool remove(const char* path);
//     };
//     class FsFile {
//       FsFile();  ~FsFile();                           // the destructor closes an open file
//       bool open(FsVolume* volume, const char* path, oflag_t flags);
//       int read(void* buffer, size_t count);           // bytes read, 0 at the end, -1 on error
//       size_t write(const void* buffer, size_t count); // bytes written (fewer: error)
//       bool close();                                   // flushes; false on error
//     };
#pragma once

#if defined(__IMXRT1062__) && !defined(ARDUINO_TEENSY40)

#include <SdFat.h>
#include <stddef.h>
#include <stdint.h>

#include "stepdance/core/fault.hpp"

namespace stepdance::platform::teensy::services {

/// The built-in slot's card: SdFat's SdioCard whose deleting destructor calls the operator delete
/// below, not the global one (see the top of this file). Lives in static storage and is never
/// deleted, so these run only after a bug; they report it and free nothing. Context: any.
class SdCardBuiltin final : public ::SdioCard {
 public:
  static void operator delete(void*) noexcept { report_delete(); }
  static void operator delete(void*, size_t) noexcept { report_delete(); }

 private:
  static void report_delete() { fault(FaultReason::kInvariant, "delete of the SD card object (never allocated)"); }
};

/// The card in the built-in slot and its volume, built in place together (storage_sd.cpp).
struct SdVolume {
  SdCardBuiltin card;
  ::FsVolume volume;
};
using SdFile = ::FsFile;

/// Starts the card in the built-in slot and mounts its volume, as SdFs::begin(SdioConfig) does.
/// False: no card, or it does not answer. Context: loop (blocks while the card answers).
inline bool sd_begin_builtin(SdVolume& sd) {
  return sd.card.begin(SdioConfig(FIFO_SDIO)) && sd.card.errorCode() == 0 && sd.volume.begin(&sd.card);
}

/// Opens `name` for reading, for writing from empty, or for writing at its end (created if
/// needed). Context: loop.
inline bool sd_open_read(SdVolume& sd, SdFile& file, const char* name) { return file.open(&sd.volume, name, O_RDONLY); }
inline bool sd_open_truncate(SdVolume& sd, SdFile& file, const char* name) {
  return file.open(&sd.volume, name, O_WRONLY | O_CREAT | O_TRUNC);
}
inline bool sd_open_append(SdVolume& sd, SdFile& file, const char* name) {
  return file.open(&sd.volume, name, O_WRONLY | O_CREAT | O_AT_END);
}

/// Bytes read (0 at the end of the file), or -1 on a card error. Context: loop.
inline int sd_read(SdFile& file, uint8_t* data, size_t length) { return file.read(data, length); }
/// Bytes written; fewer than `length` means the card failed. Context: loop.
inline size_t sd_write(SdFile& file, const uint8_t* data, size_t length) { return file.write(data, length); }
/// Flushes and closes; false if the flush failed. Context: loop.
inline bool sd_close(SdFile& file) { return file.close(); }

}  // namespace stepdance::platform::teensy::services

#endif  // __IMXRT1062__ && !ARDUINO_TEENSY40
