// Number-to-text conversion shared by Print and String (the digits Arduino sketches expect).
#pragma once

#include <stddef.h>
#include <stdint.h>

namespace stepdance::arduino {

/// Room for the longest integer text: 64 binary digits, a sign and the terminating NUL.
constexpr size_t kIntegerTextSize = 66;
/// Room for the longest float text: 309 integer digits, sign, point, kMaxFloatDigits, NUL.
constexpr size_t kFloatTextSize = 352;
/// The most digits after the point that float formatting produces (more are clamped).
constexpr int kMaxFloatDigits = 30;

/// The base a number is written in: 2..36 as given; 0 and 1 (and anything above 36) mean 10,
/// as in the Arduino core. Digits above 9 are upper-case letters.
int effective_base(int base);

/// Writes `value` in `base` (see effective_base) into text, NUL-terminated; returns the length.
/// text must hold kIntegerTextSize characters.
size_t format_unsigned(uint64_t value, int base, char* text);

/// Writes `value` in decimal with a leading '-' when negative; returns the length.
/// text must hold kIntegerTextSize characters.
size_t format_signed_decimal(int64_t value, char* text);

/// Writes `value` rounded to `digits` places after the point (clamped to 0..kMaxFloatDigits; no
/// point when 0), NUL-terminated; returns the length. Non-finite values give "nan", "inf" or
/// "-inf"; negative zero prints as "0.00" while -0.001 prints as "-0.00", as on the board.
/// Rounding is to nearest of the exact binary value, as printf does. text must hold
/// kFloatTextSize characters.
size_t format_float(double value, int digits, char* text);

}  // namespace stepdance::arduino
