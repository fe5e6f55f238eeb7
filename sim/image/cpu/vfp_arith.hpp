// The ARM floating-point pseudocode's primitives (ARMv7-M ARM A2.5 and the ARMv8-M additions)
// on binary64/binary32 bit patterns: the pieces execute_vfp_double() builds instructions from.
#pragma once

#include <cstdint>

namespace stepdance::sim::image::vfp {

/// ARM rounding modes (FPSCR.RMode encoding) plus ties-away for VRINTA/VCVTA.
enum Rounding : unsigned { kNearest = 0, kPlusInf = 1, kMinusInf = 2, kZero = 3, kAway = 4 };

constexpr uint64_t kSign64 = uint64_t{1} << 63;
constexpr uint64_t kQuiet64 = uint64_t{1} << 51;
constexpr uint64_t kDefaultNaN64 = 0x7FF8000000000000;
constexpr uint32_t kSign32 = 1u << 31;
constexpr uint32_t kDefaultNaN32 = 0x7FC00000;

/// One instruction's view of FPSCR: its controls in, its exception flags out.
struct Context {
  uint32_t fpscr;
  uint32_t flags = 0;  ///< FPSCR cumulative bits raised by this instruction
  unsigned rounding() const { return (fpscr >> 22) & 3; }
  bool flush() const { return (fpscr & (1u << 24)) != 0; }
  bool default_nan() const { return (fpscr & (1u << 25)) != 0; }
};

constexpr bool is_nan(uint64_t bits) { return (bits & ~kSign64) > 0x7FF0000000000000; }
constexpr bool is_signalling(uint64_t bits) { return is_nan(bits) && (bits & kQuiet64) == 0; }
constexpr uint64_t negate(uint64_t bits) { return bits ^ kSign64; }

/// FPUnpack's flush: with FZ a denormal becomes a zero of its sign (and IDC).
uint64_t flush_input(uint64_t bits, Context& context);
uint32_t flush_input32(uint32_t bits, Context& context);
/// FPProcessNaNs (two operands) / FPProcessNaNs3: true with `result` if an operand is a NaN.
bool process_nans(uint64_t a, uint64_t b, uint64_t& result, Context& context);
bool process_nans3(uint64_t a, uint64_t b, uint64_t c, uint64_t& result, Context& context);
/// FPProcessNaN: a signalling NaN quieted (IOC); DN gives the default NaN.
uint64_t process_nan(uint64_t bits, Context& context);

uint64_t add(uint64_t a, uint64_t b, Context& context);
uint64_t subtract(uint64_t a, uint64_t b, Context& context);
uint64_t multiply(uint64_t a, uint64_t b, Context& context);
uint64_t divide(uint64_t a, uint64_t b, Context& context);
/// FPMulAdd: addend + a * b with one rounding.
uint64_t multiply_add(uint64_t addend, uint64_t a, uint64_t b, Context& context);
uint64_t square_root(uint64_t a, Context& context);
/// FPCompare: the NZCV nibble (bits 3:0 = N Z C V). `signal_quiet`: VCMPE.
unsigned compare(uint64_t a, uint64_t b, bool signal_quiet, Context& context);
/// FPMaxNum / FPMinNum (VMAXNM, VMINNM).
uint64_t max_min_number(uint64_t a, uint64_t b, bool maximum, Context& context);

/// FPRoundInt (VRINT*): `exact` (VRINTX) raises IXC when the value changes.
uint64_t round_to_integral(uint64_t a, unsigned rounding, bool exact, Context& context);
/// FPToFixed with no fraction bits: saturating, 0 for a NaN (IOC on both).
uint32_t to_integer(uint64_t a, bool is_signed, unsigned rounding, Context& context);
uint64_t from_integer(uint32_t value, bool is_signed);
/// FPConvert between binary32 and binary64.
uint64_t widen(uint32_t a, Context& context);
uint32_t narrow(uint64_t a, Context& context);

}  // namespace stepdance::sim::image::vfp
