// Decoding the double-precision floating-point data-processing instructions (internal to
// vfp_double.cpp and its tests).
#pragma once

#include <cstdint>

namespace stepdance::sim::image::vfp {

enum class Op : uint8_t {
  kNone,
  kVmla, kVmls, kVnmla, kVnmls, kVmul, kVnmul, kVadd, kVsub, kVdiv,
  kVfma, kVfms, kVfnma, kVfnms,
  kVmovImmediate, kVmov, kVabs, kVneg, kVsqrt,
  kVcmp, kVcmpe, kVcmpZero, kVcmpeZero,
  kVcvtF64F32, kVcvtF32F64, kVcvtF64Int, kVcvtIntF64,
  kVrint, kVsel, kVmaxnm, kVminnm,
};

/// One decoded instruction: its operation and operands. Double registers d, n, m (0–15);
/// single registers sd, sm (0–31) where the operation reads or writes one.
struct Decoded {
  Op op = Op::kNone;
  uint8_t d = 0, n = 0, m = 0;
  uint8_t sd = 0, sm = 0;
  bool is_signed = false;   ///< VCVT to/from an integer
  uint8_t rounding = 0;     ///< VCVT to an integer, VRINT: a vfp::Rounding
  bool fpscr_rounding = false;  ///< … or FPSCR's mode
  bool exact = false;       ///< VRINTX
  uint8_t condition = 0;    ///< VSEL: 0 eq, 1 vs, 2 ge, 3 gt
  uint8_t immediate = 0;    ///< VMOV immediate: imm8
};

/// Decodes `instruction` (first halfword << 16 | second). op == kNone if it is not one of ours.
Decoded decode(uint32_t instruction);

}  // namespace stepdance::sim::image::vfp
