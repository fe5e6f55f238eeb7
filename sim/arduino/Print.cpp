// Arduino's Print on the host: number formatting comes from number_format.
#include "Print.h"

#include <stdarg.h>
#include <stdio.h>
#include <string.h>

#include <vector>

#include "number_format.hpp"

using stepdance::arduino::effective_base;
using stepdance::arduino::format_float;
using stepdance::arduino::format_signed_decimal;
using stepdance::arduino::format_unsigned;
using stepdance::arduino::kFloatTextSize;
using stepdance::arduino::kIntegerTextSize;

size_t Print::write(const uint8_t* buffer, size_t size) {
  size_t written = 0;
  while (written < size && write(buffer[written]) == 1) ++written;
  return written;
}

size_t Print::write(const char* text) {
  if (text == nullptr) return 0;
  return write(reinterpret_cast<const uint8_t*>(text), strlen(text));
}

size_t Print::print(const char* text) { return write(text); }
size_t Print::print(const __FlashStringHelper* text) { return write(reinterpret_cast<const char*>(text)); }
size_t Print::print(const String& text) { return write(text.c_str(), text.length()); }
size_t Print::print(char c) { return write(static_cast<uint8_t>(c)); }

size_t Print::print(unsigned char value, int base) { return print_unsigned(value, base); }
size_t Print::print(unsigned int value, int base) { return print_unsigned(value, base); }
size_t Print::print(unsigned long value, int base) { return print_unsigned(value, base); }
size_t Print::print(unsigned long long value, int base) { return print_unsigned(value, base); }

// Signed values carry their two's complement in their own width for non-decimal bases.
size_t Print::print(int value, int base) { return print_signed(value, static_cast<unsigned int>(value), base); }
size_t Print::print(long value, int base) { return print_signed(value, static_cast<unsigned long>(value), base); }
size_t Print::print(long long value, int base) {
  return print_signed(value, static_cast<unsigned long long>(value), base);
}

size_t Print::print(double value, int digits) {
  char text[kFloatTextSize];
  const size_t length = format_float(value, digits, text);
  return write(text, length);
}

size_t Print::println() { return write("\r\n", 2); }

int Print::printf(const char* format, ...) {
  char small[256];
  va_list arguments;
  va_start(arguments, format);
  const int length = vsnprintf(small, sizeof small, format, arguments);
  va_end(arguments);
  if (length < 0) return length;
  if (static_cast<size_t>(length) < sizeof small) {
    return static_cast<int>(write(small, static_cast<size_t>(length)));
  }
  std::vector<char> large(static_cast<size_t>(length) + 1);
  va_start(arguments, format);
  vsnprintf(large.data(), large.size(), format, arguments);
  va_end(arguments);
  return static_cast<int>(write(large.data(), static_cast<size_t>(length)));
}

size_t Print::print_signed(long long value, unsigned long long two_complement, int base) {
  if (base == 0) return write(static_cast<uint8_t>(two_complement));
  char text[kIntegerTextSize];
  const size_t length =
      effective_base(base) == 10 ? format_signed_decimal(value, text) : format_unsigned(two_complement, base, text);
  return write(text, length);
}

size_t Print::print_unsigned(unsigned long long value, int base) {
  if (base == 0) return write(static_cast<uint8_t>(value));
  char text[kIntegerTextSize];
  const size_t length = format_unsigned(value, base, text);
  return write(text, length);
}
