// Host IEEE 754 arithmetic under an ARM rounding mode, with the ARM's idea of underflow.
//
// The host (x86-64 SSE2, or any IEEE 754 binary64 machine) gives correctly rounded results and
// the five exception flags in every rounding mode, which is exactly what the ARM pseudocode's
// FPRound computes, with two differences fixed here: the ARM detects tininess before rounding
// (the host after), and FZ flushes a tiny result to zero (UFC, no IXC). NaN results are always
// the ARM default NaN (the host's is negative); NaN operands never reach the host.
#pragma once

#include <cfenv>
#include <cmath>
#include <cstring>
#include <limits>
#include <type_traits>

#if defined(__x86_64__) && defined(__SSE2__)
#include <xmmintrin.h>
#endif

#include "image/cpu/vfp_arith.hpp"

namespace stepdance::sim::image::vfp {

template <class T>
inline T from_bits(typename std::conditional<sizeof(T) == 8, uint64_t, uint32_t>::type bits) {
  T value;
  std::memcpy(&value, &bits, sizeof value);
  return value;
}
inline uint64_t bits_of(double value) {
  uint64_t bits;
  std::memcpy(&bits, &value, sizeof bits);
  return bits;
}
inline uint32_t bits_of(float value) {
  uint32_t bits;
  std::memcpy(&bits, &value, sizeof bits);
  return bits;
}

/// Keeps the compiler from moving floating-point work across fesetround/fetestexcept.
template <class T>
inline void fence(T& value) {
  asm volatile("" : "+m"(value));
}

uint32_t host_flags_to_fpscr(int host_flags);

#if defined(__x86_64__) && defined(__SSE2__)
// x86-64 does binary64 and binary32 arithmetic in SSE: its MXCSR holds the rounding mode and the
// flags. Setting it directly costs a few ns; <cfenv> (which also keeps the x87 unit in step)
// costs most of an emulated instruction's time.
inline uint32_t mxcsr_flags_to_fpscr(unsigned mxcsr) {
  uint32_t bits = 0;
  if (mxcsr & 0x01) bits |= 1u << 0;  // IE → IOC (bit 1, DE, has no ARM counterpart)
  if (mxcsr & 0x04) bits |= 1u << 1;  // ZE → DZC
  if (mxcsr & 0x08) bits |= 1u << 2;  // OE → OFC
  if (mxcsr & 0x10) bits |= 1u << 3;  // UE → UFC
  if (mxcsr & 0x20) bits |= 1u << 4;  // PE → IXC
  return bits;
}

/// Runs `op(args...)` under ARM rounding mode `rounding` (0–3) and ORs its exception flags
/// (FPSCR bits) into `flags`. MXCSR (rounding, flags; DAZ and FTZ off) is restored.
template <class Op, class... Args>
auto run_rounded(unsigned rounding, uint32_t& flags, Op op, Args... args) {
  static constexpr unsigned kRoundingControl[4] = {0u << 13, 2u << 13, 1u << 13, 3u << 13};  // RN RP RM RZ
  const unsigned saved = _mm_getcsr();
  _mm_setcsr((saved & ~0xE07Fu) | kRoundingControl[rounding & 3]);
  (fence(args), ...);
  auto result = op(args...);
  fence(result);
  const unsigned after = _mm_getcsr();
  _mm_setcsr(saved);
  flags |= mxcsr_flags_to_fpscr(after);
  return result;
}
#else
/// Runs `op(args...)` under ARM rounding mode `rounding` (0–3) and ORs its exception flags
/// (FPSCR bits) into `flags`. The host's rounding mode is restored.
template <class Op, class... Args>
auto run_rounded(unsigned rounding, uint32_t& flags, Op op, Args... args) {
  static constexpr int kModes[4] = {FE_TONEAREST, FE_UPWARD, FE_DOWNWARD, FE_TOWARDZERO};
  const int saved = std::fegetround();
  std::fesetround(kModes[rounding & 3]);
  std::feclearexcept(FE_ALL_EXCEPT);
  (fence(args), ...);
  auto result = op(args...);
  fence(result);
  flags |= host_flags_to_fpscr(std::fetestexcept(FE_ALL_EXCEPT));
  std::fesetround(saved);
  return result;
}
#endif

/// FPRound of `op(args...)` (a host operation giving a correctly rounded T): the ARM result's
/// bit pattern, its flags added to `context`.
template <class T, class Op, class... Args>
auto arm_rounded(Context& context, Op op, Args... args) {
  uint32_t flags = 0;
  const T result = run_rounded(context.rounding(), flags, op, args...);
  if (std::isnan(result)) {
    context.flags |= flags;
    if constexpr (sizeof(T) == 8) {
      return kDefaultNaN64;
    } else {
      return kDefaultNaN32;
    }
  }
  const T magnitude = std::fabs(result);
  const T smallest_normal = std::numeric_limits<T>::min();
  const bool inexact = (flags & (1u << 4)) != 0;
  if (magnitude <= smallest_normal && (result != 0 || inexact)) {
    bool tiny = magnitude < smallest_normal;
    if (!tiny && inexact) {  // rounded up to the smallest normal: was the exact value below it?
      uint32_t ignored = 0;
      tiny = std::fabs(run_rounded(kZero, ignored, op, args...)) < smallest_normal;
    }
    flags &= ~(1u << 3);
    if (tiny && context.flush()) {
      context.flags |= (flags & ~(1u << 4)) | (1u << 3);
      return bits_of(std::copysign(T(0), result));
    }
    if (tiny && inexact) flags |= 1u << 3;
  }
  context.flags |= flags;
  return bits_of(result);
}

}  // namespace stepdance::sim::image::vfp
