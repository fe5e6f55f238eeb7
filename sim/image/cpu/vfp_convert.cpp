// ARM conversions on binary64 (ARMv7-M ARM A2.5: FPToFixed, FixedToFP, FPConvert; ARMv8-M
// FPRoundInt): integers by explicit rounding, binary64 → binary32 by the host under the ARM
// rounding mode (vfp_host.hpp).
#include <cmath>

#include "image/cpu/vfp_arith.hpp"
#include "image/cpu/vfp_double.hpp"
#include "image/cpu/vfp_host.hpp"

namespace stepdance::sim::image::vfp {
namespace {

// The integral value nearest `x` by `rounding` (x finite). Exact: no host rounding mode.
double integral(double x, unsigned rounding) {
  switch (rounding) {
    case kPlusInf: return std::ceil(x);
    case kMinusInf: return std::floor(x);
    case kZero: return std::trunc(x);
    case kAway: return std::round(x);
    default: {
      const double below = std::floor(x);
      const double fraction = x - below;  // exact: below and x share an exponent range
      if (fraction > 0.5) return below + 1;
      if (fraction < 0.5) return below;
      return std::fmod(below, 2.0) == 0 ? below : below + 1;  // a tie: the even one
    }
  }
}

}  // namespace

uint64_t round_to_integral(uint64_t a, unsigned rounding, bool exact, Context& context) {
  a = flush_input(a, context);
  if (is_nan(a)) return process_nan(a, context);
  const double x = from_bits<double>(a);
  if (std::isinf(x) || x == 0) return a;
  const double rounded = std::copysign(integral(x, rounding), x);  // a zero keeps the sign
  if (exact && rounded != x) context.flags |= fpscr::kIxc;
  return bits_of(rounded);
}

uint32_t to_integer(uint64_t a, bool is_signed, unsigned rounding, Context& context) {
  a = flush_input(a, context);
  if (is_nan(a)) {
    context.flags |= fpscr::kIoc;
    return 0;
  }
  const double x = from_bits<double>(a);
  const double rounded = std::isinf(x) ? x : integral(x, rounding);
  const double low = is_signed ? -2147483648.0 : 0.0;
  const double high = is_signed ? 2147483647.0 : 4294967295.0;
  if (rounded < low || rounded > high) {
    context.flags |= fpscr::kIoc;
    const double saturated = rounded < low ? low : high;
    return is_signed ? static_cast<uint32_t>(static_cast<int32_t>(saturated)) : static_cast<uint32_t>(saturated);
  }
  if (rounded != x) context.flags |= fpscr::kIxc;
  return is_signed ? static_cast<uint32_t>(static_cast<int32_t>(rounded)) : static_cast<uint32_t>(rounded);
}

uint64_t from_integer(uint32_t value, bool is_signed) {
  const double x = is_signed ? static_cast<double>(static_cast<int32_t>(value)) : static_cast<double>(value);
  return bits_of(x);  // every 32-bit integer is a binary64 exactly
}

// FPConvert binary32 → binary64: exact; a NaN keeps its sign and payload (quieted).
uint64_t widen(uint32_t a, Context& context) {
  a = flush_input32(a, context);
  if ((a & ~kSign32) > 0x7F800000) {
    if ((a & (1u << 22)) == 0) context.flags |= fpscr::kIoc;
    if (context.default_nan()) return kDefaultNaN64;
    const uint64_t sign = uint64_t{a & kSign32} << 32;
    return sign | 0x7FF8000000000000 | (uint64_t{a & 0x3FFFFF} << 29);
  }
  return bits_of(static_cast<double>(from_bits<float>(a)));
}

// FPConvert binary64 → binary32: rounded by FPSCR; a NaN keeps its sign and the top of its payload.
uint32_t narrow(uint64_t a, Context& context) {
  a = flush_input(a, context);
  if (is_nan(a)) {
    if (is_signalling(a)) context.flags |= fpscr::kIoc;
    if (context.default_nan()) return kDefaultNaN32;
    const auto sign = static_cast<uint32_t>(a >> 32) & kSign32;
    return sign | 0x7FC00000 | static_cast<uint32_t>((a >> 29) & 0x3FFFFF);
  }
  return arm_rounded<float>(context, [](double x) { return static_cast<float>(x); }, from_bits<double>(a));
}

}  // namespace stepdance::sim::image::vfp
