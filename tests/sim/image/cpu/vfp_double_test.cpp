// The software double-precision unit against IEEE 754 facts and the ARM ARM's tables. Every
// expected bit pattern is worked out by hand in the comment beside it; the instruction words are
// arm-none-eabi-as's encodings of the named instruction (-mcpu=cortex-m7 -mfpu=fpv5-d16).
#include <gtest/gtest.h>

#include "image/cpu/vfp_double.hpp"

namespace stepdance::sim::image {
namespace {

// Encodings, all with d1 as the destination, d2 (n) and d3 (m) as operands (s3 = top of d1).
constexpr uint32_t kVmla = 0xEE021B03, kVnmul = 0xEE221B43, kVadd = 0xEE321B03, kVsub = 0xEE321B43;
constexpr uint32_t kVmul = 0xEE221B03, kVdiv = 0xEE821B03, kVfma = 0xEEA21B03, kVfms = 0xEEA21B43;
constexpr uint32_t kVfnma = 0xEE921B43, kVfnms = 0xEE921B03, kVsqrt = 0xEEB11BC3;
constexpr uint32_t kVmovOne = 0xEEB71B00, kVmovMinusEighthD7 = 0xEEBC7B00, kVabs = 0xEEB01BC3, kVneg = 0xEEB11B43;
constexpr uint32_t kVcmp = 0xEEB41B43, kVcmpe = 0xEEB41BC3, kVcmpZero = 0xEEB51B40;
constexpr uint32_t kVcvtF64F32 = 0xEEB71AE1, kVcvtF32F64 = 0xEEF71BC1, kVcvtF64S32 = 0xEEB81BE1, kVcvtF64U32 = 0xEEB81B61;
constexpr uint32_t kVcvtS32F64 = 0xEEFD1BC1, kVcvtU32F64 = 0xEEFC1BC1, kVcvtrS32F64 = 0xEEFD1B41;
constexpr uint32_t kVrintr = 0xEEB61B43, kVrintz = 0xEEB61BC3, kVrintx = 0xEEB71B43;
constexpr uint32_t kVrinta = 0xFEB81B43, kVrintn = 0xFEB91B43, kVrintp = 0xFEBA1B43, kVrintm = 0xFEBB1B43;
constexpr uint32_t kVcvtaS32 = 0xFEFC1BC1, kVcvtnU32 = 0xFEFD1B41, kVcvtpS32 = 0xFEFE1BC1, kVcvtmU32 = 0xFEFF1B41;
constexpr uint32_t kVseleq = 0xFE021B03, kVselgt = 0xFE321B03, kVmaxnm = 0xFE821B03, kVminnm = 0xFE821B43;

constexpr uint32_t kRn = 0u << 22, kRp = 1u << 22, kRm = 2u << 22, kRz = 3u << 22;
constexpr uint32_t kFlags = fpscr::kIoc | fpscr::kDzc | fpscr::kOfc | fpscr::kUfc | fpscr::kIxc | fpscr::kIdc;

constexpr uint64_t kOne = 0x3FF0000000000000, kTwo = 0x4000000000000000;
constexpr uint64_t kPlusInf = 0x7FF0000000000000, kMinusZero = 0x8000000000000000;
constexpr uint64_t kDefaultNaN = 0x7FF8000000000000;

struct Result {
  VfpRegisters regs;
  uint64_t d1() const { return regs.d[1]; }
  uint32_t s3() const { return regs.s(3); }
  uint32_t flags() const { return regs.fpscr & kFlags; }
  uint32_t nzcv() const { return regs.fpscr >> 28; }
};

// Runs `instruction` with d1 = `d`, d2 = `n`, d3 = `m` and FPSCR = `fpscr`.
Result run(uint32_t instruction, uint64_t n, uint64_t m, uint32_t fpscr = 0, uint64_t d = 0) {
  Result result;
  result.regs.d[1] = d;
  result.regs.d[2] = n;
  result.regs.d[3] = m;
  result.regs.fpscr = fpscr;
  EXPECT_EQ(execute_vfp_double(instruction, result.regs), VfpOutcome::kExecuted) << std::hex << instruction;
  return result;
}

// Runs a one-operand instruction on d1 (VCVT.*.F64 reads d1 and writes s3).
Result run_on_d1(uint32_t instruction, uint64_t d1, uint32_t fpscr = 0) { return run(instruction, 0, 0, fpscr, d1); }

TEST(VfpDouble, AddingHalfAnUlpToOneRoundsByTheMode) {
  const uint64_t half_ulp = 0x3CA0000000000000;  // 2^-53: exactly half of 1.0's ulp (2^-52)
  EXPECT_EQ(run(kVadd, kOne, half_ulp, kRn).d1(), kOne);  // a tie: 1.0 has the even significand
  EXPECT_EQ(run(kVadd, kOne, half_ulp, kRn).flags(), fpscr::kIxc);
  EXPECT_EQ(run(kVadd, kOne, half_ulp, kRp).d1(), kOne + 1);  // 1 + 2^-52
  EXPECT_EQ(run(kVadd, kOne, half_ulp, kRm).d1(), kOne);
  EXPECT_EQ(run(kVadd, kOne, half_ulp, kRz).d1(), kOne);
  EXPECT_EQ(run(kVadd, kOne, 0x3CA8000000000000, kRn).d1(), kOne + 1);  // 1.5 × 2^-53: above the tie
  EXPECT_EQ(run(kVadd, kOne, kOne).d1(), kTwo);
  EXPECT_EQ(run(kVadd, kOne, kOne).flags(), 0u);
}

TEST(VfpDouble, AnExactZeroDifferenceIsMinusZeroOnlyRoundingDown) {
  EXPECT_EQ(run(kVsub, kOne, kOne, kRn).d1(), 0u);
  EXPECT_EQ(run(kVsub, kOne, kOne, kRm).d1(), kMinusZero);
  EXPECT_EQ(run(kVsub, kOne, kOne, kRm).flags(), 0u);
}

TEST(VfpDouble, OverflowGivesInfinityOrTheLargestFiniteByMode) {
  const uint64_t largest = 0x7FEFFFFFFFFFFFFF;
  EXPECT_EQ(run(kVmul, largest, kTwo, kRn).d1(), kPlusInf);
  EXPECT_EQ(run(kVmul, largest, kTwo, kRn).flags(), fpscr::kOfc | fpscr::kIxc);
  EXPECT_EQ(run(kVmul, largest, kTwo, kRz).d1(), largest);
  EXPECT_EQ(run(kVmul, largest, kTwo, kRm).d1(), largest);
  EXPECT_EQ(run(kVmul, largest, kTwo, kRz).flags(), fpscr::kOfc | fpscr::kIxc);
}

TEST(VfpDouble, DivisionByZeroAndInvalidOperations) {
  EXPECT_EQ(run(kVdiv, kOne, 0).d1(), kPlusInf);
  EXPECT_EQ(run(kVdiv, kOne, 0).flags(), fpscr::kDzc);
  EXPECT_EQ(run(kVdiv, kOne | kMinusZero, 0).d1(), kPlusInf | kMinusZero);
  EXPECT_EQ(run(kVdiv, 0, 0).d1(), kDefaultNaN);  // the ARM default NaN is positive (x86's is not)
  EXPECT_EQ(run(kVdiv, 0, 0).flags(), fpscr::kIoc);
  EXPECT_EQ(run(kVmul, kPlusInf, 0).d1(), kDefaultNaN);
  EXPECT_EQ(run(kVsub, kPlusInf, kPlusInf).flags(), fpscr::kIoc);
}

TEST(VfpDouble, SquareRoots) {
  EXPECT_EQ(run(kVsqrt, 0, 0x4010000000000000).d1(), kTwo);  // √4 = 2 exactly
  EXPECT_EQ(run(kVsqrt, 0, 0x4010000000000000).flags(), 0u);
  EXPECT_EQ(run(kVsqrt, 0, kTwo).d1(), 0x3FF6A09E667F3BCDu);  // √2 = 1.4142135623730951
  EXPECT_EQ(run(kVsqrt, 0, kTwo).flags(), fpscr::kIxc);
  EXPECT_EQ(run(kVsqrt, 0, kMinusZero).d1(), kMinusZero);
  EXPECT_EQ(run(kVsqrt, 0, kOne | kMinusZero).d1(), kDefaultNaN);
  EXPECT_EQ(run(kVsqrt, 0, kOne | kMinusZero).flags(), fpscr::kIoc);
}

TEST(VfpDouble, NaNsPropagateSignallingFirstThenTheFirstOperand) {
  const uint64_t quiet_a = 0x7FF800000000000A, quiet_b = 0xFFF800000000000B, signalling = 0x7FF0000000000002;
  Result r = run(kVadd, quiet_a, signalling);
  EXPECT_EQ(r.d1(), 0x7FF8000000000002u);  // the signalling NaN, quieted (bit 51 set)
  EXPECT_EQ(r.flags(), fpscr::kIoc);
  r = run(kVadd, quiet_a, quiet_b);
  EXPECT_EQ(r.d1(), quiet_a);
  EXPECT_EQ(r.flags(), 0u);
  EXPECT_EQ(run(kVadd, kOne, quiet_b).d1(), quiet_b);
  EXPECT_EQ(run(kVsub, kOne, quiet_b).d1(), quiet_b);  // VSUB does not negate a NaN
  r = run(kVadd, quiet_a, signalling, fpscr::kDn);
  EXPECT_EQ(r.d1(), kDefaultNaN);
  EXPECT_EQ(r.flags(), fpscr::kIoc);
  EXPECT_EQ(run(kVadd, quiet_a, kOne, fpscr::kDn).d1(), kDefaultNaN);
  // VNMUL negates the product, a NaN included (FPNeg after FPMul).
  EXPECT_EQ(run(kVnmul, 0x7FF8000000000007, kOne).d1(), 0xFFF8000000000007u);
}

TEST(VfpDouble, CompareSetsNzcvAndOnlyVcmpeSignalsOnAQuietNaN) {
  const uint64_t quiet = 0x7FF8000000000001, signalling = 0x7FF0000000000001;
  // d1 is the first operand, d3 the second.
  EXPECT_EQ(run(kVcmp, 0, kTwo, 0, kOne).nzcv(), 0x8u);  // less: N
  EXPECT_EQ(run(kVcmp, 0, kOne, 0, kTwo).nzcv(), 0x2u);  // greater: C
  EXPECT_EQ(run(kVcmp, 0, kOne, 0, kOne).nzcv(), 0x6u);  // equal: Z C
  Result r = run(kVcmp, 0, kOne, 0, quiet);
  EXPECT_EQ(r.nzcv(), 0x3u);  // unordered: C V
  EXPECT_EQ(r.flags(), 0u);
  r = run(kVcmpe, 0, kOne, 0, quiet);
  EXPECT_EQ(r.nzcv(), 0x3u);
  EXPECT_EQ(r.flags(), fpscr::kIoc);
  EXPECT_EQ(run(kVcmp, 0, kOne, 0, signalling).flags(), fpscr::kIoc);
  EXPECT_EQ(run(kVcmpZero, 0, 0, 0, kMinusZero).nzcv(), 0x6u);  // -0 == +0
  EXPECT_EQ(run(kVcmpZero, 0, 0, 0, kOne | kMinusZero).nzcv(), 0x8u);
  EXPECT_EQ(run(kVcmp, 0, kOne, 0x40000000u | fpscr::kIxc, kOne).regs.fpscr, 0x60000000u | fpscr::kIxc);  // old NZCV replaced, flags kept
}

TEST(VfpDouble, ConversionToIntegersSaturatesAndGivesZeroForNaN) {
  const uint64_t three_billion = 0x41E65A0BC0000000;  // 3e9 = 0xB2D05E00 = 1.3969838619232178 × 2^31
  Result r = run_on_d1(kVcvtS32F64, three_billion);
  EXPECT_EQ(r.s3(), 0x7FFFFFFFu);
  EXPECT_EQ(r.flags(), fpscr::kIoc);
  EXPECT_EQ(run_on_d1(kVcvtS32F64, three_billion | kMinusZero).s3(), 0x80000000u);
  EXPECT_EQ(run_on_d1(kVcvtU32F64, three_billion).s3(), 3000000000u);
  r = run_on_d1(kVcvtS32F64, 0x7FF8000000000000);
  EXPECT_EQ(r.s3(), 0u);
  EXPECT_EQ(r.flags(), fpscr::kIoc);
  const uint64_t two_and_half = 0x4004000000000000, three_and_half = 0x400C000000000000;
  r = run_on_d1(kVcvtS32F64, two_and_half | kMinusZero);  // toward zero: -2
  EXPECT_EQ(r.s3(), 0xFFFFFFFEu);
  EXPECT_EQ(r.flags(), fpscr::kIxc);
  EXPECT_EQ(run_on_d1(kVcvtrS32F64, two_and_half, kRn).s3(), 2u);  // ties to even
  EXPECT_EQ(run_on_d1(kVcvtrS32F64, three_and_half, kRn).s3(), 4u);
  EXPECT_EQ(run_on_d1(kVcvtrS32F64, two_and_half, kRp).s3(), 3u);
  r = run_on_d1(kVcvtU32F64, kOne | kMinusZero);  // -1 saturates to 0
  EXPECT_EQ(r.s3(), 0u);
  EXPECT_EQ(r.flags(), fpscr::kIoc);
  r = run_on_d1(kVcvtU32F64, 0xBFE0000000000000);  // -0.5 toward zero is 0: only inexact
  EXPECT_EQ(r.s3(), 0u);
  EXPECT_EQ(r.flags(), fpscr::kIxc);
  EXPECT_EQ(run_on_d1(kVcvtaS32, two_and_half | kMinusZero).s3(), 0xFFFFFFFDu);  // away: -3
  EXPECT_EQ(run_on_d1(kVcvtnU32, two_and_half).s3(), 2u);
  EXPECT_EQ(run_on_d1(kVcvtpS32, two_and_half | kMinusZero).s3(), 0xFFFFFFFEu);  // up: -2
  EXPECT_EQ(run_on_d1(kVcvtmU32, two_and_half).s3(), 2u);
}

TEST(VfpDouble, ConversionFromIntegersIsExact) {
  Result r;
  r.regs.set_s(3, 0xFFFFFFFF);
  ASSERT_EQ(execute_vfp_double(kVcvtF64S32, r.regs), VfpOutcome::kExecuted);
  EXPECT_EQ(r.d1(), 0xBFF0000000000000u);  // -1.0
  r.regs.set_s(3, 0xFFFFFFFF);
  ASSERT_EQ(execute_vfp_double(kVcvtF64U32, r.regs), VfpOutcome::kExecuted);
  EXPECT_EQ(r.d1(), 0x41EFFFFFFFE00000u);  // 2^32 - 1 = (2 - 2^-31) × 2^31
  EXPECT_EQ(r.flags(), 0u);
}

TEST(VfpDouble, ConversionBetweenSingleAndDouble) {
  EXPECT_EQ(run_on_d1(kVcvtF32F64, kOne + 1, kRn).s3(), 0x3F800000u);  // 1 + 2^-52 → 1.0f
  EXPECT_EQ(run_on_d1(kVcvtF32F64, kOne + 1, kRn).flags(), fpscr::kIxc);
  EXPECT_EQ(run_on_d1(kVcvtF32F64, kOne + 1, kRp).s3(), 0x3F800001u);  // … or 1 + 2^-23 rounding up
  Result r = run_on_d1(kVcvtF32F64, 0x4C70000000000000);  // 2^200 (exponent 1223 = 0x4C7)
  EXPECT_EQ(r.s3(), 0x7F800000u);
  EXPECT_EQ(r.flags(), fpscr::kOfc | fpscr::kIxc);
  r = run_on_d1(kVcvtF32F64, 0x7FF4000000000000);  // signalling, payload bit 50 → bit 21
  EXPECT_EQ(r.s3(), 0x7FE00000u);
  EXPECT_EQ(r.flags(), fpscr::kIoc);
  Result w;
  w.regs.set_s(3, 0x00000001);  // the smallest single denormal, 2^-149: a normal double
  ASSERT_EQ(execute_vfp_double(kVcvtF64F32, w.regs), VfpOutcome::kExecuted);
  EXPECT_EQ(w.d1(), 0x36A0000000000000u);  // exponent 1023 - 149 = 874 = 0x36A
  w.regs.fpscr = fpscr::kFz;
  w.regs.set_s(3, 0x00000001);
  ASSERT_EQ(execute_vfp_double(kVcvtF64F32, w.regs), VfpOutcome::kExecuted);
  EXPECT_EQ(w.d1(), 0u);
  EXPECT_EQ(w.flags(), fpscr::kIdc);
}

TEST(VfpDouble, FlushToZeroOnInputsAndTinyResults) {
  Result r = run(kVadd, 1, 0, fpscr::kFz);  // the smallest denormal is flushed: IDC
  EXPECT_EQ(r.d1(), 0u);
  EXPECT_EQ(r.flags(), fpscr::kIdc);
  EXPECT_EQ(run(kVadd, 1, 0).d1(), 1u);
  const uint64_t two_to_minus_1000 = 0x0170000000000000, two_to_minus_30 = 0x3E10000000000000;
  r = run(kVmul, two_to_minus_1000, two_to_minus_30);  // 2^-1030: a denormal, exact
  EXPECT_EQ(r.d1(), uint64_t{1} << 44);                // 2^-1030 = 2^44 × 2^-1074
  EXPECT_EQ(r.flags(), 0u);                            // exact: no underflow without a trap
  r = run(kVmul, two_to_minus_1000, two_to_minus_30, fpscr::kFz);
  EXPECT_EQ(r.d1(), 0u);
  EXPECT_EQ(r.flags(), fpscr::kUfc);  // flushed: underflow, not inexact
  // VABS/VNEG never flush or look at NaNs.
  r = run(kVabs, 0, 0x8000000000000001, fpscr::kFz);
  EXPECT_EQ(r.d1(), 1u);
  EXPECT_EQ(r.flags(), 0u);
  EXPECT_EQ(run(kVneg, 0, 0x7FF0000000000001).d1(), 0xFFF0000000000001u);
}

TEST(VfpDouble, TininessIsDetectedBeforeRounding) {
  // (1 + 2^-52) × 2^-1022 × (1 - 2^-52) = (1 - 2^-104) × 2^-1022: below the smallest normal
  // before rounding, which rounds it up to exactly 2^-1022. The ARM reports underflow.
  const Result r = run(kVmul, 0x0010000000000001, 0x3FEFFFFFFFFFFFFE);
  EXPECT_EQ(r.d1(), 0x0010000000000000u);
  EXPECT_EQ(r.flags(), fpscr::kUfc | fpscr::kIxc);
}

TEST(VfpDouble, FusedMultiplyAddRoundsOnceAndVmlaTwice) {
  const uint64_t x = 0x3FF0000002000000;            // 1 + 2^-27 (fraction bit 25); x² = 1 + 2^-26 + 2^-54
  const uint64_t one_plus = 0x3FF0000004000000;     // 1 + 2^-26 (fraction bit 26)
  const uint64_t tiny = 0x3C90000000000000;         // 2^-54
  Result r = run(kVfma, x, x, 0, one_plus | kMinusZero);
  EXPECT_EQ(r.d1(), tiny);
  EXPECT_EQ(r.flags(), 0u);
  r = run(kVmla, x, x, 0, one_plus | kMinusZero);  // x² rounds to 1 + 2^-26 first
  EXPECT_EQ(r.d1(), 0u);
  EXPECT_EQ(r.flags(), fpscr::kIxc);
  EXPECT_EQ(run(kVfms, x, x, 0, one_plus).d1(), tiny | kMinusZero);               // d - n·m
  EXPECT_EQ(run(kVfnma, x, x, 0, one_plus | kMinusZero).d1(), tiny | kMinusZero);  // -d - n·m
  EXPECT_EQ(run(kVfnms, x, x, 0, one_plus).d1(), tiny);                            // -d + n·m
  r = run(kVfma, kPlusInf, 0, 0, 0x7FF8000000000123);  // quiet NaN + ∞ × 0: invalid anyway
  EXPECT_EQ(r.d1(), kDefaultNaN);
  EXPECT_EQ(r.flags(), fpscr::kIoc);
}

TEST(VfpDouble, MoveImmediateExpandsImm8) {
  EXPECT_EQ(run(kVmovOne, 0, 0).d1(), kOne);
  VfpRegisters regs;
  ASSERT_EQ(execute_vfp_double(kVmovMinusEighthD7, regs), VfpOutcome::kExecuted);
  EXPECT_EQ(regs.d[7], 0xBFC0000000000000u);  // -0.125 = -2^-3: exponent 1020 = 0x3FC
}

TEST(VfpDouble, RoundToIntegral) {
  const uint64_t two_and_half = 0x4004000000000000, minus_half = 0xBFE0000000000000;
  EXPECT_EQ(run(kVrinta, 0, two_and_half).d1(), 0x4008000000000000u);  // 3
  EXPECT_EQ(run(kVrintn, 0, two_and_half).d1(), kTwo);
  EXPECT_EQ(run(kVrintm, 0, minus_half).d1(), 0xBFF0000000000000u);  // -1
  EXPECT_EQ(run(kVrintp, 0, minus_half).d1(), kMinusZero);           // -0 keeps its sign
  EXPECT_EQ(run(kVrintz, 0, 0xC005A00000000000).d1(), 0xC000000000000000u);  // -2.703125 → -2
  Result r = run(kVrintx, 0, two_and_half, kRn);
  EXPECT_EQ(r.d1(), kTwo);
  EXPECT_EQ(r.flags(), fpscr::kIxc);
  r = run(kVrintr, 0, two_and_half, kRp);
  EXPECT_EQ(r.d1(), 0x4008000000000000u);
  EXPECT_EQ(r.flags(), 0u);
}

TEST(VfpDouble, SelectAndMaxMinNumber) {
  Result r;
  r.regs.d[2] = kOne;
  r.regs.d[3] = kTwo;
  r.regs.apsr = 1u << 30;  // Z
  ASSERT_EQ(execute_vfp_double(kVseleq, r.regs), VfpOutcome::kExecuted);
  EXPECT_EQ(r.d1(), kOne);
  r.regs.apsr = (1u << 31) | (1u << 28);  // N and V, Z clear: gt holds
  ASSERT_EQ(execute_vfp_double(kVselgt, r.regs), VfpOutcome::kExecuted);
  EXPECT_EQ(r.d1(), kOne);
  r.regs.apsr = 1u << 31;  // N only: gt fails
  ASSERT_EQ(execute_vfp_double(kVselgt, r.regs), VfpOutcome::kExecuted);
  EXPECT_EQ(r.d1(), kTwo);
  EXPECT_EQ(run(kVmaxnm, 0x7FF8000000000000, kOne).d1(), kOne);  // a quiet NaN loses to a number
  EXPECT_EQ(run(kVminnm, kOne, 0x7FF8000000000000).d1(), kOne);
  EXPECT_EQ(run(kVmaxnm, kMinusZero, 0).d1(), 0u);
  EXPECT_EQ(run(kVminnm, 0, kMinusZero).d1(), kMinusZero);
  r = run(kVmaxnm, 0x7FF0000000000001, kOne);
  EXPECT_EQ(r.d1(), 0x7FF8000000000001u);
  EXPECT_EQ(r.flags(), fpscr::kIoc);
}

TEST(VfpDouble, RecognisesOnlyDoublePrecisionDataProcessing) {
  EXPECT_TRUE(is_vfp_double_data_op(kVadd));
  EXPECT_TRUE(is_vfp_double_data_op(kVcvtF64F32));  // sz = 0, but its result is a double
  EXPECT_TRUE(is_vfp_double_data_op(0xEE3EFB0D));   // vadd.f64 d15, d14, d13
  EXPECT_FALSE(is_vfp_double_data_op(0xEE710A21));  // vadd.f32 s1, s2, s3
  EXPECT_FALSE(is_vfp_double_data_op(0xED901B00));  // vldr d1, [r0]
  EXPECT_FALSE(is_vfp_double_data_op(0xEC510B11));  // vmov r0, r1, d1
  EXPECT_FALSE(is_vfp_double_data_op(kVadd | (1u << 22)));  // d17: FPv5-D16 has D0-D15 only
  EXPECT_FALSE(is_vfp_double_data_op(0xBF00BF00));
  VfpRegisters regs;
  regs.d[1] = 42;
  EXPECT_EQ(execute_vfp_double(0xEE710A21, regs), VfpOutcome::kNotMine);
  EXPECT_EQ(regs.d[1], 42u);
  const VfpOperands operands = vfp_operands(kVcvtS32F64);
  EXPECT_EQ(operands.writes, 1u << 1);  // s3 lives in d1
  EXPECT_EQ(vfp_operands(kVcmp).writes, 0u);
}

}  // namespace
}  // namespace stepdance::sim::image
