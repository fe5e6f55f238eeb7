// Number formatting for protocol replies.
#include "stepdance/core/text_writer.hpp"

#include <math.h>

namespace stepdance {

void TextWriter::clear() {
  size_ = 0;
  overflowed_ = false;
  if (capacity_ > 0) data_[0] = '\0';
}

// Never writes past capacity and keeps the text terminated; overflow is remembered so a caller can
// refuse a truncated reply instead of sending it.
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

// Negated in 64 bits: −INT32_MIN does not fit an int32.
TextWriter& TextWriter::signed_number(int32_t value) {
  if (value < 0) {
    character('-');
    return unsigned_number(static_cast<uint32_t>(-(static_cast<int64_t>(value))));
  }
  return unsigned_number(static_cast<uint32_t>(value));
}

// Fixed-point text without printf (large on the firmware, and not something to call from an ISR).
// At most 6 decimals, and ±1e9 or more prints "ovf": the whole part must fit a uint32.
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
  return padded(static_cast<uint32_t>(scaled - whole * scale), decimals);
}

// Whole numbers below 10^15 print exactly (no exponent, no ".0"), as a JSON client expects an
// integer-valued parameter; anything else goes through rounded() with `digits` significant digits.
TextWriter& TextWriter::significant(double value, uint8_t digits) {
  if (isnan(value) || isinf(value)) return fixed(value, 0);
  if (digits < 1) digits = 1;
  if (digits > 9) digits = 9;
  const double magnitude = fabs(value);
  if (magnitude != floor(magnitude) || magnitude >= 1e15) return rounded(value, digits);
  if (value < 0) character('-');
  return whole_number(magnitude);
}

namespace {

// magnitude / 10^exponent. 10^exponent is subnormal (and inexact) below 10^-307: scaled up first.
double mantissa_of(double magnitude, int exponent) {
  return exponent < -307 ? magnitude * 1e20 / pow(10.0, exponent + 20) : magnitude / pow(10.0, exponent);
}

}  // namespace

// `magnitude` (> 0) rounded to `digits` significant digits. log10 can land one off next to a power
// of ten, so the mantissa is brought into [1, 10) first; a mantissa that rounds up to 10
// (9.9999995 to seven digits) carries into the exponent: 1.000000 × 10^(exponent + 1).
TextWriter::Significand TextWriter::round_significant(double magnitude, uint8_t digits) {
  int exponent = static_cast<int>(floor(log10(magnitude)));
  double mantissa = mantissa_of(magnitude, exponent);
  if (mantissa >= 10.0) {
    ++exponent;
    mantissa /= 10.0;
  } else if (mantissa < 1.0) {
    --exponent;
    mantissa *= 10.0;
  }
  const double one = pow(10.0, digits - 1);  // the mantissa 1.0… as a whole number of digits
  double rounded = floor(mantissa * one + 0.5);
  if (rounded >= 10.0 * one) {
    rounded = one;
    ++exponent;
  }
  return {rounded, one, exponent};
}

// Trailing zeros of the fraction are dropped. The form follows the rounded value (docs/rpc.md):
// an exponent below 10^-3 and from 10^15, so 0.00099999999 to six digits is "0.001" and
// 999999999999999.9 to nine is "1e15".
TextWriter& TextWriter::rounded(double value, uint8_t digits) {
  const Significand significand = round_significant(fabs(value), digits);
  if (value < 0) character('-');
  if (significand.exponent < -3 || significand.exponent >= 15) return scientific(significand);
  return plain(fabs(value), digits, significand.exponent);
}

// "d.ddde±x": one digit 1..9 before the point, the significand's digits after it.
TextWriter& TextWriter::scientific(const Significand& significand) {
  const double whole = floor(significand.digits / significand.one);
  whole_and_fraction(static_cast<uint32_t>(significand.digits - whole * significand.one), whole, significand.one);
  character('e');
  const int exponent = significand.exponent;
  if (exponent < 0) character('-');
  return unsigned_number(static_cast<uint32_t>(exponent < 0 ? -exponent : exponent));
}

// Plain: digits − 1 − exponent decimals (none from 10^(digits − 1) up: every whole digit is kept).
TextWriter& TextWriter::plain(double magnitude, uint8_t digits, int exponent) {
  const int wanted_decimals = digits - 1 - exponent;
  const int decimals = wanted_decimals < 0 ? 0 : wanted_decimals;  // at most 11
  const double scale = pow(10.0, decimals);
  const double scaled = floor(magnitude * scale + 0.5);
  const double whole = floor(scaled / scale);
  return whole_and_fraction(static_cast<uint32_t>(scaled - whole * scale), whole, scale);
}

// Prints whole, then `fraction` out of `scale` (a power of ten) without its trailing zeros.
TextWriter& TextWriter::whole_and_fraction(uint32_t fraction, double whole, double scale) {
  uint8_t places = 0;
  for (double unit = 1.0; unit < scale; unit *= 10.0) ++places;
  while (places > 0 && fraction % 10 == 0) {
    fraction /= 10;
    --places;
  }
  whole_number(whole);
  if (places > 0) character('.').padded(fraction, places);
  return *this;
}

TextWriter& TextWriter::whole_number(double value) {
  // 0 ≤ value ≤ 10^15, whole: two uint32 halves keep 64-bit division out of the firmware.
  const double high = floor(value / 1e9);
  const uint32_t low = static_cast<uint32_t>(value - high * 1e9);
  if (high == 0) return unsigned_number(low);
  unsigned_number(static_cast<uint32_t>(high));
  return padded(low, 9);
}

TextWriter& TextWriter::padded(uint32_t value, uint8_t places) {
  char digits[12];
  if (places > sizeof(digits) - 1) places = sizeof(digits) - 1;
  for (int i = places - 1; i >= 0; --i) {
    digits[i] = static_cast<char>('0' + value % 10);
    value /= 10;
  }
  digits[places] = '\0';
  return text(digits);
}

}  // namespace stepdance
