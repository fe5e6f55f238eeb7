// Builds reply lines for the host protocols in a fixed buffer (no printf, no heap).
#pragma once

#include <stddef.h>
#include <stdint.h>

namespace stepdance {

/// Appends text and numbers to caller-owned storage. Text that does not fit is cut off and
/// overflowed() turns true, so a caller can refuse or report instead of sending a torn reply.
/// Context: any (touches only its own buffer).
class TextWriter {
 public:
  TextWriter(char* storage, size_t capacity) : data_(storage), capacity_(capacity) { clear(); }

  void clear();
  TextWriter& text(const char* value);
  TextWriter& character(char value);
  TextWriter& unsigned_number(uint32_t value);
  TextWriter& signed_number(int32_t value);
  /// A decimal number rounded to `decimals` places (0..6); NaN prints "nan", ±inf "inf"/"-inf",
  /// and magnitudes of 10^9 or more print "ovf" (no host protocol expects such numbers).
  TextWriter& fixed(double value, uint8_t decimals);
  /// A number to `digits` significant digits (1..9) as short as it reads: whole numbers below
  /// 10^15 with every digit; others rounded (half away from zero) with trailing zeros dropped,
  /// plain from 0.001 up (every whole digit from 10^9 up) and with an exponent below 0.001 and
  /// from 10^15 ("1.2345e-5", "2.5e20"); NaN and ±inf as fixed() prints them.
  TextWriter& significant(double value, uint8_t digits);

  const char* c_str() const { return data_; }
  size_t size() const { return size_; }
  bool overflowed() const { return overflowed_; }

 private:
  TextWriter& padded(uint32_t value, uint8_t places);
  TextWriter& whole_number(double value);
  // A positive magnitude rounded to n significant digits: `digits` (a whole number,
  // one ≤ digits < 10 × one, one = 10^(n − 1)) × 10^(exponent − n + 1).
  struct Significand {
    double digits;
    double one;
    int exponent;
  };
  static Significand round_significant(double magnitude, uint8_t digits);
  TextWriter& rounded(double value, uint8_t digits);
  TextWriter& scientific(const Significand& significand);
  TextWriter& plain(double magnitude, uint8_t digits, int exponent);
  TextWriter& whole_and_fraction(uint32_t fraction, double whole, double scale);

  char* data_;
  size_t capacity_;
  size_t size_ = 0;
  bool overflowed_ = false;
};

}  // namespace stepdance
