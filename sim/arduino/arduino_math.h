// Arduino math helpers on the host: PI constants, min/max/constrain/map, sq, random().
//
// The Arduino core defines most of these as macros. Here they are constants and templates, so
// they cannot break standard headers included after Arduino.h (a `min` macro would).
#pragma once

#include <stdint.h>

#include <type_traits>

constexpr double PI = 3.14159265358979323846;
constexpr double HALF_PI = PI / 2;
constexpr double TWO_PI = PI * 2;
constexpr double DEG_TO_RAD = PI / 180;
constexpr double RAD_TO_DEG = 180 / PI;

/// The smaller / larger of two values, in their common type (as the Arduino macros compute).
template <typename A, typename B>
constexpr std::common_type_t<A, B> min(const A& a, const B& b) {
  return b < a ? b : a;
}
template <typename A, typename B>
constexpr std::common_type_t<A, B> max(const A& a, const B& b) {
  return a < b ? b : a;
}

/// value limited to low..high, in the common type of the three.
template <typename T, typename L, typename H>
constexpr std::common_type_t<T, L, H> constrain(const T& value, const L& low, const H& high) {
  return value < low ? low : (high < value ? high : value);
}

/// value * value.
template <typename T>
constexpr auto sq(const T& value) -> decltype(value * value) {
  return value * value;
}

/// Degrees to radians and back.
constexpr double radians(double degrees) { return degrees * DEG_TO_RAD; }
constexpr double degrees(double radians) { return radians * RAD_TO_DEG; }

/// Re-maps value from in_min..in_max onto out_min..out_max (no clamping).
/// Integer arguments: long arithmetic truncated toward zero, as the Arduino core does.
/// Any floating-point argument: computed and returned in the common floating type.
/// An empty input range (in_min == in_max) returns out_min instead of dividing by zero.
template <typename V, typename A, typename B, typename C, typename D>
constexpr auto map(V value, A in_min, B in_max, C out_min, D out_max) {
  using Common = std::common_type_t<V, A, B, C, D>;
  if constexpr (std::is_floating_point_v<Common>) {
    if (in_max == in_min) return static_cast<Common>(out_min);
    return (static_cast<Common>(value) - in_min) * (static_cast<Common>(out_max) - out_min) /
               (static_cast<Common>(in_max) - in_min) +
           out_min;
  } else {
    const long range_in = static_cast<long>(in_max) - static_cast<long>(in_min);
    if (range_in == 0) return static_cast<long>(out_min);
    return (static_cast<long>(value) - static_cast<long>(in_min)) *
               (static_cast<long>(out_max) - static_cast<long>(out_min)) / range_in +
           static_cast<long>(out_min);
  }
}

/// Seeds random(). The same seed gives the same sequence on every run and every machine; the
/// generator starts as if seeded with 1. Context: loop.
void randomSeed(unsigned long seed);
/// A pseudo-random number in 0 .. howbig − 1 (0 when howbig ≤ 0). Context: loop.
long random(long howbig);
/// A pseudo-random number in howsmall .. howbig − 1 (howsmall when howsmall ≥ howbig).
/// Context: loop.
long random(long howsmall, long howbig);
