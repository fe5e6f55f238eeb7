// Stand-in declarations of Teensyduino's SD library, modelling its allocation: SD.open() returns a
// File that owns a heap-allocated file object, shared by copies and freed by the last one. Our
// backend does not use this library (it uses SdFat without the heap); a sketch that does pulls
// operator new and delete into its image, and the build's no-heap check reports it. The
// definitions in SD.cpp behave as if no card were inserted.
#pragma once

#include <stddef.h>
#include <stdint.h>

#define BUILTIN_SDCARD 254
#define FILE_READ 0
#define FILE_WRITE 1

/// An open file on the card, or a closed handle (false).
class File {
 public:
  File() = default;
  File(const File& other);
  File& operator=(const File& other);
  ~File();

  size_t read(void* buffer, size_t length);
  size_t write(const void* buffer, size_t length);
  void close();
  operator bool();

  struct Shared;  // the heap object an open File refers to

 private:
  explicit File(Shared* shared) : shared_(shared) {}
  void release();
  Shared* shared_ = nullptr;
  friend class SDClass;
};

/// The card: start it, open and remove files.
class SDClass {
 public:
  bool begin(uint8_t chip_select_pin);
  File open(const char* path, uint8_t mode);
  bool remove(const char* path);
  /// The old Arduino SD interface, which Teensyduino's SD.h keeps: it ignores the speed, and its
  /// unused parameter warns under -Wextra there as here. Kept on purpose: it proves that
  /// scripts/build-teensy.sh includes third-party headers as system headers (-isystem), which
  /// the real core and its libraries need under our -Werror.
  bool init(uint32_t speed, uint8_t chip_select_pin) { return begin(chip_select_pin); }

 private:
  bool card_ = false;
};

extern SDClass SD;
