// Arduino's Print on the host: text and number output for Serial and any other byte sink.
#pragma once

#include <stddef.h>
#include <stdint.h>

#include "WString.h"

/// Number bases for print(value, base).
constexpr int DEC = 10;
constexpr int HEX = 16;
constexpr int OCT = 8;
constexpr int BIN = 2;

/// Marks a string literal the Teensy would keep in flash; on the host it is an ordinary string.
#define F(string_literal) (reinterpret_cast<const __FlashStringHelper*>(string_literal))

/// Something that bytes can be written to. Subclasses implement write(uint8_t) and, if they can
/// do better than byte by byte, write(buffer, size).
///
/// Formatting, as the Arduino core prints:
///  - integers in decimal by default; print(value, HEX / OCT / BIN / any base 2..36) writes
///    upper-case digits without prefix or padding. A negative number in a base other than 10
///    writes the two's complement of its type (−1 as an int in HEX is FFFFFFFF; a long is 64
///    bits on a 64-bit host where the Teensy's is 32). Base 0 writes the low byte itself.
///  - char writes the character; unsigned char (uint8_t) writes a number; bool writes 1 or 0.
///  - floating point with 2 digits after the point by default, print(value, digits) for more
///    or fewer (0: no point), rounded to nearest; "nan", "inf", "-inf" for non-finite values.
///  - println() ends the line with "\r\n".
/// Every function returns the number of bytes written. Context: loop.
class Print {
 public:
  virtual ~Print() = default;

  /// Writes one byte; returns 1, or 0 if it could not be written.
  virtual size_t write(uint8_t byte) = 0;
  /// Writes size bytes; returns how many were written (stops at the first refused byte).
  virtual size_t write(const uint8_t* buffer, size_t size);
  size_t write(const char* text);
  size_t write(const char* buffer, size_t size) { return write(reinterpret_cast<const uint8_t*>(buffer), size); }
  // Integer arguments write their low byte (write(0) would otherwise be ambiguous).
  size_t write(int byte) { return write(static_cast<uint8_t>(byte)); }
  size_t write(unsigned int byte) { return write(static_cast<uint8_t>(byte)); }
  size_t write(long byte) { return write(static_cast<uint8_t>(byte)); }
  size_t write(unsigned long byte) { return write(static_cast<uint8_t>(byte)); }

  /// Bytes that can be written without waiting (0 if unknown).
  virtual int availableForWrite() { return 0; }
  /// Waits until written bytes have left (nothing to wait for on the host).
  virtual void flush() {}

  size_t print(const char* text);
  size_t print(const __FlashStringHelper* text);
  size_t print(const String& text);
  size_t print(char c);
  size_t print(unsigned char value, int base = DEC);
  size_t print(int value, int base = DEC);
  size_t print(unsigned int value, int base = DEC);
  size_t print(long value, int base = DEC);
  size_t print(unsigned long value, int base = DEC);
  size_t print(long long value, int base = DEC);
  size_t print(unsigned long long value, int base = DEC);
  size_t print(double value, int digits = 2);

  /// Ends the line: "\r\n".
  size_t println();
  /// print(value) or print(value, format), then "\r\n".
  template <typename T>
  size_t println(const T& value) {
    const size_t written = print(value);
    return written + println();
  }
  template <typename T>
  size_t println(const T& value, int format) {
    const size_t written = print(value, format);
    return written + println();
  }

  /// printf-style formatting (the Teensy core has it too). Returns the bytes written.
  int printf(const char* format, ...) __attribute__((format(printf, 2, 3)));

 private:
  size_t print_signed(long long value, unsigned long long two_complement, int base);
  size_t print_unsigned(unsigned long long value, int base);
};
