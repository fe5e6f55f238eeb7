// The double-precision half of the Cortex-M7's FPv5-D16 floating-point unit, in software.
//
// Debian's unicorn 2.0.1 models the Cortex-M7 with a single-precision-only FPU: every
// double-precision data-processing instruction is undefined to it. The CPU (vfp_hooks.cpp)
// hands those instructions here. Loads, stores and moves between core and D registers are not
// data-processing instructions: the emulator runs them itself.
#pragma once

#include <array>
#include <cstdint>

namespace stepdance::sim::image {

/// The FPU state a double-precision instruction reads and writes.
struct VfpRegisters {
  /// D0–D15 as IEEE 754 binary64 bit patterns; S(2n) is the low word of Dn, S(2n+1) the high.
  std::array<uint64_t, 16> d{};
  /// FPSCR (ARMv7-M ARM A2.5.3): NZCV 31:28, DN 25, FZ 24, RMode 23:22, IDC 7,
  /// IXC 4, UFC 3, OFC 2, DZC 1, IOC 0.
  uint32_t fpscr = 0;
  /// APSR with N, Z, C, V in bits 31:28: read by VSEL only (vfp_reads_apsr()).
  uint32_t apsr = 0;

  uint32_t s(unsigned index) const { return static_cast<uint32_t>(d[index >> 1] >> (32 * (index & 1))); }
  void set_s(unsigned index, uint32_t value) {
    const unsigned shift = 32 * (index & 1);
    d[index >> 1] = (d[index >> 1] & ~(uint64_t{0xFFFFFFFF} << shift)) | (uint64_t{value} << shift);
  }
};

enum class VfpOutcome : uint8_t {
  kNotMine,   ///< not a double-precision data-processing instruction of FPv5-D16: nothing changed
  kExecuted,  ///< executed: registers and FPSCR (flags, NZCV) updated
};

/// FPSCR bits.
namespace fpscr {
constexpr uint32_t kIoc = 1u << 0, kDzc = 1u << 1, kOfc = 1u << 2, kUfc = 1u << 3, kIxc = 1u << 4, kIdc = 1u << 7;
constexpr uint32_t kFz = 1u << 24, kDn = 1u << 25;
constexpr unsigned kRModeShift = 22;
constexpr uint32_t kNzcvMask = 0xFu << 28;
}  // namespace fpscr

/// True if `instruction` (first halfword << 16 | second halfword) is a double-precision
/// floating-point data-processing instruction of the Cortex-M7's FPv5-D16 (ARMv7-M ARM A6.4
/// "floating-point data-processing instructions" with sz = 1, VCVT.F64.F32, and the FPv5
/// additions VSEL, VMAXNM/VMINNM, VRINT*, VCVT{A,N,P,M}). Context: any.
bool is_vfp_double_data_op(uint32_t instruction);

/// True if `instruction` reads the APSR condition flags (VSEL): the caller fills regs.apsr.
bool vfp_reads_apsr(uint32_t instruction);

/// True if `instruction` may be conditional inside an IT block (the T1 forms with 0xEE; the
/// FPv5 0xFE forms are always unconditional).
bool vfp_is_conditional(uint32_t instruction);

/// The D registers an instruction reads and writes (bit n = Dn; a single register Sk counts as
/// D(k/2)), so a caller need move only those. Both zero for an instruction that is not ours.
struct VfpOperands {
  uint16_t reads = 0;
  uint16_t writes = 0;
};
VfpOperands vfp_operands(uint32_t instruction);

/// Executes `instruction` on `regs` with the ARM semantics (FPSCR rounding mode, FZ, DN, NaN
/// propagation, cumulative exception flags) — or returns kNotMine and changes nothing.
/// Context: any; the host's floating-point environment is restored before it returns.
VfpOutcome execute_vfp_double(uint32_t instruction, VfpRegisters& regs);

}  // namespace stepdance::sim::image
