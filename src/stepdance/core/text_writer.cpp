// Number formatting for protocol replies.
#include "stepdance/core/text_writer.hpp"

#include <math.h>

namespace stepdance {

void TextWriter::clear() {
  size_ = 0;
  overflowed_ = false;
  if (capacity_ > 0) data_[0] = '\0';
}

TextWriter& TextWriter::character(char value) {
  if (size_ + 1 >= capacity_) {
    overflowed_ = true;
    return *this;
  }
  data_[size_++] = value;
  data_[size_] = '\0';
  return *this;
}

TextWriter& TextWriter::text(const char* value) {
  while (*value != '\0') character(*value++);
  return *this;
}

TextWriter& TextWriter::unsigned_number(uint32_t value) {
  char digits[10];
  int count = 0;
  do {
    digits[count++] = static_cast<char>('0' + value % 10);
    value /= 10;
  } while (value != 0);
  while (count > 0) character(digits[--count]);
  return *this;
}

TextWriter& TextWriter::signed_number(int32_t value) {
  if (value < 0) {
    character('-');
    return unsigned_number(static_cast<uint32_t>(-(static_cast<int64_t>(value))));
  }
  return unsigned_number(static_cast<uint32_t>(value));
}

TextWriter& TextWriter::fixed(double value, uint8_t decimals) {
  if (isnan(value)) return text("nan");
  if (isinf(value)) return text(value < 0 ? "-inf" : "inf");
  if (decimals > 6) decimals = 6;
  uint32_t scale = 1;
  for (uint8_t i = 0; i < decimals; ++i) scale *= 10;
  if (fabs(value) >= 1e9) return text("ovf");
  // Whole units and the fraction split in double arithmetic (exact below 2^53), which keeps
  // 64-bit integer division — a libgcc call on the M7 — out of the firmware.
  const double scaled = floor(fabs(value) * scale + 0.5);
  const double whole = floor(scaled / scale);
  if (value < 0 && scaled != 0.0) character('-');
  unsigned_number(static_cast<uint32_t>(whole));
  if (decimals == 0) return *this;
  character('.');
  uint32_t fraction = static_cast<uint32_t>(scaled - whole * scale);
  for (uint32_t place = scale / 10; place > 0; place /= 10) {
    character(static_cast<char>('0' + fraction / place));
    fraction %= place;
  }
  return *this;
}

}  // namespace stepdance
