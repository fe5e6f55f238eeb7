// Number-to-text conversion shared by Print and String.
#include "number_format.hpp"

#include <math.h>
#include <stdio.h>
#include <string.h>

namespace stepdance::arduino {

int effective_base(int base) { return (base < 2 || base > 36) ? 10 : base; }

size_t format_unsigned(uint64_t value, int base, char* text) {
  const uint64_t radix = static_cast<uint64_t>(effective_base(base));
  char reversed[kIntegerTextSize];
  size_t length = 0;
  do {
    const auto digit = static_cast<char>(value % radix);
    reversed[length++] = static_cast<char>(digit < 10 ? '0' + digit : 'A' + digit - 10);
    value /= radix;
  } while (value != 0);
  for (size_t i = 0; i < length; ++i) text[i] = reversed[length - 1 - i];
  text[length] = '\0';
  return length;
}

size_t format_signed_decimal(int64_t value, char* text) {
  if (value >= 0) return format_unsigned(static_cast<uint64_t>(value), 10, text);
  text[0] = '-';
  // Negate in unsigned arithmetic so INT64_MIN has a magnitude too.
  const uint64_t magnitude = 0u - static_cast<uint64_t>(value);
  return 1 + format_unsigned(magnitude, 10, text + 1);
}

size_t format_float(double value, int digits, char* text) {
  if (isnan(value)) {
    memcpy(text, "nan", 4);
    return 3;
  }
  if (isinf(value)) {
    const char* word = value < 0 ? "-inf" : "inf";
    const size_t length = strlen(word);
    memcpy(text, word, length + 1);
    return length;
  }
  if (digits < 0) digits = 0;
  if (digits > kMaxFloatDigits) digits = kMaxFloatDigits;
  // Negative zero prints unsigned, as on the board (a tiny negative value keeps its '-').
  if (value == 0.0) value = 0.0;
  int length = snprintf(text, kFloatTextSize, "%.*f", digits, value);
  if (length < 0) length = 0;
  if (length >= static_cast<int>(kFloatTextSize)) length = static_cast<int>(kFloatTextSize) - 1;
  return static_cast<size_t>(length);
}

}  // namespace stepdance::arduino
