// The ARM floating-point primitives on binary64: NaN handling and flushing by the ARM
// pseudocode (ARMv7-M ARM A2.5.x, FPUnpack/FPProcessNaNs/FPMulAdd/FPCompare; ARMv8-M FPMaxNum),
// the arithmetic itself by the host under the ARM rounding mode (vfp_host.hpp).
#include "image/cpu/vfp_arith.hpp"

#include "image/cpu/vfp_host.hpp"
#include "image/cpu/vfp_double.hpp"

namespace stepdance::sim::image::vfp {
namespace {

constexpr bool is_zero(uint64_t bits) { return (bits & ~kSign64) == 0; }
constexpr bool is_infinity(uint64_t bits) { return (bits & ~kSign64) == 0x7FF0000000000000; }

}  // namespace

uint32_t host_flags_to_fpscr(int host_flags) {
  uint32_t bits = 0;
  if (host_flags & FE_INVALID) bits |= fpscr::kIoc;
  if (host_flags & FE_DIVBYZERO) bits |= fpscr::kDzc;
  if (host_flags & FE_OVERFLOW) bits |= fpscr::kOfc;
  if (host_flags & FE_UNDERFLOW) bits |= fpscr::kUfc;
  if (host_flags & FE_INEXACT) bits |= fpscr::kIxc;
  return bits;
}

uint64_t flush_input(uint64_t bits, Context& context) {
  if (!context.flush() || (bits & 0x7FF0000000000000) != 0 || is_zero(bits)) return bits;
  context.flags |= fpscr::kIdc;
  return bits & kSign64;
}

uint32_t flush_input32(uint32_t bits, Context& context) {
  if (!context.flush() || (bits & 0x7F800000) != 0 || (bits & ~kSign32) == 0) return bits;
  context.flags |= fpscr::kIdc;
  return bits & kSign32;
}

uint64_t process_nan(uint64_t bits, Context& context) {
  if (is_signalling(bits)) context.flags |= fpscr::kIoc;
  return context.default_nan() ? kDefaultNaN64 : bits | kQuiet64;
}

bool process_nans(uint64_t a, uint64_t b, uint64_t& result, Context& context) {
  return process_nans3(a, b, 0, result, context);
}

// Signalling NaNs first, in operand order; then quiet ones, in operand order.
bool process_nans3(uint64_t a, uint64_t b, uint64_t c, uint64_t& result, Context& context) {
  const uint64_t operands[3] = {a, b, c};
  for (uint64_t operand : operands) {
    if (!is_signalling(operand)) continue;
    result = process_nan(operand, context);
    return true;
  }
  for (uint64_t operand : operands) {
    if (!is_nan(operand)) continue;
    result = process_nan(operand, context);
    return true;
  }
  return false;
}

namespace {

// A two-operand operation: flush, NaNs, then the host.
template <class Op>
uint64_t binary(uint64_t a, uint64_t b, Context& context, Op op) {
  a = flush_input(a, context);
  b = flush_input(b, context);
  uint64_t result;
  if (process_nans(a, b, result, context)) return result;
  return arm_rounded<double>(context, op, from_bits<double>(a), from_bits<double>(b));
}

}  // namespace

uint64_t add(uint64_t a, uint64_t b, Context& context) {
  return binary(a, b, context, [](double x, double y) { return x + y; });
}
uint64_t subtract(uint64_t a, uint64_t b, Context& context) {
  return binary(a, b, context, [](double x, double y) { return x - y; });
}
uint64_t multiply(uint64_t a, uint64_t b, Context& context) {
  return binary(a, b, context, [](double x, double y) { return x * y; });
}
uint64_t divide(uint64_t a, uint64_t b, Context& context) {
  return binary(a, b, context, [](double x, double y) { return x / y; });
}

// FPMulAdd: a quiet-NaN addend with infinity × zero is still an invalid operation (default NaN).
uint64_t multiply_add(uint64_t addend, uint64_t a, uint64_t b, Context& context) {
  addend = flush_input(addend, context);
  a = flush_input(a, context);
  b = flush_input(b, context);
  const bool inf_times_zero = (is_infinity(a) && is_zero(b)) || (is_zero(a) && is_infinity(b));
  uint64_t result;
  const bool nan = process_nans3(addend, a, b, result, context);
  if (is_nan(addend) && !is_signalling(addend) && inf_times_zero) {
    context.flags |= fpscr::kIoc;
    return kDefaultNaN64;
  }
  if (nan) return result;
  return arm_rounded<double>(context, [](double x, double y, double z) { return std::fma(x, y, z); },
                             from_bits<double>(a), from_bits<double>(b), from_bits<double>(addend));
}

uint64_t square_root(uint64_t a, Context& context) {
  a = flush_input(a, context);
  if (is_nan(a)) return process_nan(a, context);
  return arm_rounded<double>(context, [](double x) { return std::sqrt(x); }, from_bits<double>(a));
}

// FPCompare: unordered 0011 (IOC for a signalling NaN, or any NaN with VCMPE); equal 0110;
// less 1000; greater 0010.
unsigned compare(uint64_t a, uint64_t b, bool signal_quiet, Context& context) {
  a = flush_input(a, context);
  b = flush_input(b, context);
  if (is_nan(a) || is_nan(b)) {
    if (signal_quiet || is_signalling(a) || is_signalling(b)) context.flags |= fpscr::kIoc;
    return 0x3;
  }
  const double x = from_bits<double>(a), y = from_bits<double>(b);
  if (x == y) return 0x6;
  return x < y ? 0x8 : 0x2;
}

// FPMaxNum/FPMinNum: one quiet NaN loses to a number; then FPMax/FPMin, where +0 > -0.
uint64_t max_min_number(uint64_t a, uint64_t b, bool maximum, Context& context) {
  const uint64_t loser = maximum ? 0xFFF0000000000000 : 0x7FF0000000000000;
  const bool a_quiet = is_nan(a) && !is_signalling(a), b_quiet = is_nan(b) && !is_signalling(b);
  if (a_quiet && !b_quiet) a = loser;
  if (b_quiet && !a_quiet) b = loser;
  a = flush_input(a, context);
  b = flush_input(b, context);
  uint64_t result;
  if (process_nans(a, b, result, context)) return result;
  if (is_zero(a) && is_zero(b)) return maximum ? (a & b) : (a | b);  // signs: AND for max, OR for min
  const double x = from_bits<double>(a), y = from_bits<double>(b);
  return (maximum ? x > y : x < y) ? a : b;
}

}  // namespace stepdance::sim::image::vfp
