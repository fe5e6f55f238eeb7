// The ONLY door from the Teensy backend to SdFat, the card library Teensyduino bundles
// (libraries/SdFat, Bill Greiman's SdFat 2.x). Only storage_sd.cpp includes it.
//
// Why SdFat and not Teensyduino's SD library: SD's open() allocates every File on the heap and
// frees it from the File's destructor. SdFat's volume and file objects keep their state inside
// themselves, so ours live in static storage and are built in place on first use.
//
// The CI stand-in (targets/teensy/stand-in/SdFat.h) declares exactly these, with these signatures:
//
//   <SdFat.h>
//     #define FIFO_SDIO                                 // the built-in slot's SDIO mode
//     #define O_RDONLY, O_WRONLY, O_CREAT, O_TRUNC, O_AT_END   // open flags, of type oflag_t
//     class SdioConfig { explicit SdioConfig(uint8_t options); };
//     class FsVolume { bool remove(const char* path); };
//     class SdFs : public FsVolume {                    // the card and its FAT/exFAT volume
//       SdFs();  bool begin(SdioConfig config);         // false: no card, or it does not answer
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

namespace stepdance::platform::teensy::services {

using SdVolume = ::SdFs;
using SdFile = ::FsFile;

/// Starts the card in the built-in slot. Context: loop (blocks while the card answers).
inline bool sd_begin_builtin(SdVolume& volume) { return volume.begin(SdioConfig(FIFO_SDIO)); }

/// Opens `name` for reading, for writing from empty, or for writing at its end (created if
/// needed). Context: loop.
inline bool sd_open_read(SdVolume& volume, SdFile& file, const char* name) {
  return file.open(&volume, name, O_RDONLY);
}
inline bool sd_open_truncate(SdVolume& volume, SdFile& file, const char* name) {
  return file.open(&volume, name, O_WRONLY | O_CREAT | O_TRUNC);
}
inline bool sd_open_append(SdVolume& volume, SdFile& file, const char* name) {
  return file.open(&volume, name, O_WRONLY | O_CREAT | O_AT_END);
}

/// Bytes read (0 at the end of the file), or -1 on a card error. Context: loop.
inline int sd_read(SdFile& file, uint8_t* data, size_t length) { return file.read(data, length); }
/// Bytes written; fewer than `length` means the card failed. Context: loop.
inline size_t sd_write(SdFile& file, const uint8_t* data, size_t length) { return file.write(data, length); }
/// Flushes and closes; false if the flush failed. Context: loop.
inline bool sd_close(SdFile& file) { return file.close(); }

}  // namespace stepdance::platform::teensy::services

#endif  // __IMXRT1062__ && !ARDUINO_TEENSY40
