// Teensy's SD library on the host: SD and File over the board's storage (hal::storage()).
//
// In the simulator the card is a folder of the run's output directory (<board>.sd/), so files a
// sketch writes can be inspected after the run and files placed there beforehand can be read.
// Names are plain file names (no folders), at most 63 characters.
#pragma once

#include <stddef.h>
#include <stdint.h>

#include "Stream.h"

/// The chip-select value that names the Teensy 4.1's built-in card slot.
constexpr uint8_t BUILTIN_SDCARD = 254;
/// open() modes, numbered as in Teensy's SD library.
constexpr uint8_t FILE_READ = 0;
constexpr uint8_t FILE_WRITE = 1;        ///< append to the end (the file is created if missing)
constexpr uint8_t FILE_WRITE_BEGIN = 2;  ///< write from the start; on the host the file is emptied first

/// An open file, or a closed one (false). Reading goes through a 64-byte buffer, so available()
/// is the number of bytes buffered (non-zero until the end of the file), not the whole rest.
/// Copies share the open file but not the buffer: read through one copy only. Context: loop.
class File : public Stream {
 public:
  File() = default;

  /// True while the file is open.
  explicit operator bool() const { return handle_ >= 0; }
  /// The name it was opened with ("" when closed).
  const char* name() const { return name_; }

  int available() override;
  int read() override;
  int peek() override;
  /// Reads up to `length` bytes; returns how many were read (0 at the end or when closed).
  int read(void* buffer, size_t length);
  size_t write(uint8_t byte) override;
  size_t write(const uint8_t* data, size_t length) override;
  using Print::write;
  /// Closes the file; the handle becomes false. Closing a closed file does nothing.
  void close();

 private:
  friend class SDClass;
  File(int handle, const char* name, bool writable);
  bool fill();

  int handle_ = -1;
  bool writable_ = false;
  char name_[64] = {};
  uint8_t buffer_[64] = {};
  size_t buffered_ = 0;
  size_t next_ = 0;
};

/// The card. Context: loop.
class SDClass {
 public:
  /// True if the board has storage (a simulated board always does once the simulation gives it
  /// an output folder). The chip-select pin is not used.
  bool begin(uint8_t chip_select_pin = BUILTIN_SDCARD);
  /// Opens `path` (FILE_READ, FILE_WRITE or FILE_WRITE_BEGIN); a false File on failure.
  File open(const char* path, uint8_t mode = FILE_READ);
  /// True if `path` can be opened for reading.
  bool exists(const char* path);
  /// Not supported by the board storage interface: returns false and leaves the file.
  bool remove(const char* path);
};

/// The board's card.
extern SDClass SD;
