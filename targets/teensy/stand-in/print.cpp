// Arduino's Print formatting for the CI firmware image: integers in any base from 2 to 36, floating
// point with a fixed number of decimals (rounded half up; "nan", "inf", "ovf" beyond 2^32 - 1, as
// Arduino prints them).
#include <Arduino.h>
#include <stdint.h>

namespace {

// Writes `value` in `base` (2..36; others print as decimal) through `out`.
size_t print_unsigned(Print& out, unsigned long value, int base) {
  if (base < 2 || base > 36) base = 10;
  char digits[33];  // 32 binary digits and the terminator
  char* cursor = digits + sizeof(digits) - 1;
  *cursor = '\0';
  do {
    const unsigned long digit = value % static_cast<unsigned long>(base);
    value /= static_cast<unsigned long>(base);
    *--cursor = static_cast<char>(digit < 10 ? '0' + digit : 'A' + digit - 10);
  } while (value != 0);
  return out.write(cursor);
}

}  // namespace

size_t Print::write(const uint8_t* data, size_t length) {
  size_t written = 0;
  while (written < length && write(data[written]) == 1) ++written;
  return written;
}

size_t Print::print(long value, int base) {
  if (base == 10 && value < 0) {
    return print('-') + print_unsigned(*this, 0ul - static_cast<unsigned long>(value), 10);
  }
  return print_unsigned(*this, static_cast<unsigned long>(value), base);
}

size_t Print::print(unsigned long value, int base) { return print_unsigned(*this, value, base); }

size_t Print::print(double value, int digits) {
  if (value != value) return print("nan");
  if (value - value != 0.0) return print("inf");  // only an infinity minus itself is not 0
  if (value > 4294967295.0 || value < -4294967295.0) return print("ovf");
  size_t n = 0;
  if (value < 0.0) {
    n += print('-');
    value = -value;
  }
  double rounding = 0.5;
  for (int i = 0; i < digits; ++i) rounding /= 10.0;
  value += rounding;
  if (value > 4294967295.0) return n + print("ovf");
  const unsigned long whole = static_cast<unsigned long>(value);
  n += print_unsigned(*this, whole, 10);
  if (digits > 0) n += print('.');
  double fraction = value - static_cast<double>(whole);
  for (int i = 0; i < digits; ++i) {
    fraction *= 10.0;
    const int digit = static_cast<int>(fraction);
    n += print(static_cast<char>('0' + digit));
    fraction -= digit;
  }
  return n;
}
