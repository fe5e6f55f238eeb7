// Executing the decoded double-precision instructions (the ARM pseudocode of each instruction,
// ARMv7-M ARM A7.7, on the primitives of vfp_arith.hpp).
#include "image/cpu/vfp_double.hpp"

#include "image/cpu/vfp_arith.hpp"
#include "image/cpu/vfp_decode.hpp"

namespace stepdance::sim::image {
namespace {

using vfp::Context;
using vfp::Decoded;
using vfp::Op;

// VFPExpandImm for binary64: sign imm8<7>, exponent NOT(imm8<6>):imm8<6>×8:imm8<5:4>,
// fraction imm8<3:0> followed by 48 zeros.
uint64_t expand_immediate(uint8_t imm8) {
  const uint64_t b6 = (imm8 >> 6) & 1;
  const uint64_t exponent = ((b6 ^ 1) << 10) | (b6 ? 0xFFu << 2 : 0) | ((imm8 >> 4) & 3);
  return static_cast<uint64_t>(imm8 >> 7) << 63 | exponent << 52 | uint64_t{imm8 & 0xFu} << 48;
}

// VSEL's condition on APSR.NZCV: eq (Z), vs (V), ge (N == V), gt (Z == 0 and N == V).
bool condition_holds(uint8_t condition, uint32_t apsr) {
  const bool n = (apsr >> 31) & 1, z = (apsr >> 30) & 1, v = (apsr >> 28) & 1;
  switch (condition) {
    case 0: return z;
    case 1: return v;
    case 2: return n == v;
    default: return !z && n == v;
  }
}

// VMLA, VMLS, VNMLA, VNMLS (two roundings) and VMUL, VNMUL.
uint64_t multiply_accumulate(const Decoded& x, const VfpRegisters& regs, Context& c) {
  const uint64_t product = vfp::multiply(regs.d[x.n], regs.d[x.m], c);
  const uint64_t dd = regs.d[x.d];
  switch (x.op) {
    case Op::kVmla: return vfp::add(dd, product, c);
    case Op::kVmls: return vfp::add(dd, vfp::negate(product), c);
    case Op::kVnmla: return vfp::add(vfp::negate(dd), vfp::negate(product), c);
    case Op::kVnmls: return vfp::add(vfp::negate(dd), product, c);
    case Op::kVnmul: return vfp::negate(product);
    default: return product;
  }
}

// VFMA d + n·m, VFMS d + (−n)·m, VFNMA −d + (−n)·m, VFNMS −d + n·m: one rounding.
uint64_t fused(const Decoded& x, const VfpRegisters& regs, Context& c) {
  const bool negate_n = x.op == Op::kVfms || x.op == Op::kVfnma;
  const bool negate_d = x.op == Op::kVfnma || x.op == Op::kVfnms;
  const uint64_t n = negate_n ? vfp::negate(regs.d[x.n]) : regs.d[x.n];
  const uint64_t d = negate_d ? vfp::negate(regs.d[x.d]) : regs.d[x.d];
  return vfp::multiply_add(d, n, regs.d[x.m], c);
}

// The instructions whose result is one D register.
uint64_t double_result(const Decoded& x, const VfpRegisters& regs, Context& c) {
  const uint64_t dn = regs.d[x.n], dm = regs.d[x.m];
  switch (x.op) {
    case Op::kVadd: return vfp::add(dn, dm, c);
    case Op::kVsub: return vfp::subtract(dn, dm, c);
    case Op::kVdiv: return vfp::divide(dn, dm, c);
    case Op::kVfma: case Op::kVfms: case Op::kVfnma: case Op::kVfnms: return fused(x, regs, c);
    case Op::kVmovImmediate: return expand_immediate(x.immediate);
    case Op::kVmov: return dm;
    case Op::kVabs: return dm & ~vfp::kSign64;
    case Op::kVneg: return vfp::negate(dm);
    case Op::kVsqrt: return vfp::square_root(dm, c);
    case Op::kVcvtF64F32: return vfp::widen(regs.s(x.sm), c);
    case Op::kVcvtIntF64: return vfp::from_integer(regs.s(x.sm), x.is_signed);
    case Op::kVrint: return vfp::round_to_integral(dm, x.fpscr_rounding ? c.rounding() : x.rounding, x.exact, c);
    case Op::kVsel: return condition_holds(x.condition, regs.apsr) ? dn : dm;
    case Op::kVmaxnm: return vfp::max_min_number(dn, dm, true, c);
    case Op::kVminnm: return vfp::max_min_number(dn, dm, false, c);
    default: return multiply_accumulate(x, regs, c);
  }
}

}  // namespace

bool is_vfp_double_data_op(uint32_t instruction) { return vfp::decode(instruction).op != Op::kNone; }

VfpOperands vfp_operands(uint32_t instruction) {
  const Decoded x = vfp::decode(instruction);
  VfpOperands operands;
  if (x.op == Op::kNone) return operands;
  const auto bit = [](unsigned index) { return static_cast<uint16_t>(1u << index); };
  // Reading every named register is harmless: the unused fields decode to some register.
  operands.reads = bit(x.d) | bit(x.n) | bit(x.m) | bit(x.sd >> 1) | bit(x.sm >> 1);
  const bool single_result = x.op == Op::kVcvtF32F64 || x.op == Op::kVcvtF64Int;
  const bool no_result = x.op == Op::kVcmp || x.op == Op::kVcmpe || x.op == Op::kVcmpZero || x.op == Op::kVcmpeZero;
  operands.writes = no_result ? 0 : single_result ? bit(x.sd >> 1) : bit(x.d);
  return operands;
}

bool vfp_reads_apsr(uint32_t instruction) { return vfp::decode(instruction).op == Op::kVsel; }

bool vfp_is_conditional(uint32_t instruction) { return (instruction >> 24) == 0xEE; }

VfpOutcome execute_vfp_double(uint32_t instruction, VfpRegisters& regs) {
  const Decoded x = vfp::decode(instruction);
  if (x.op == Op::kNone) return VfpOutcome::kNotMine;
  Context c{regs.fpscr};
  switch (x.op) {
    case Op::kVcmp: case Op::kVcmpe: case Op::kVcmpZero: case Op::kVcmpeZero: {
      const bool zero = x.op == Op::kVcmpZero || x.op == Op::kVcmpeZero;
      const bool signal = x.op == Op::kVcmpe || x.op == Op::kVcmpeZero;
      const unsigned nzcv = vfp::compare(regs.d[x.d], zero ? 0 : regs.d[x.m], signal, c);
      regs.fpscr = (regs.fpscr & ~fpscr::kNzcvMask) | nzcv << 28;
      break;
    }
    case Op::kVcvtF32F64: regs.set_s(x.sd, vfp::narrow(regs.d[x.m], c)); break;
    case Op::kVcvtF64Int:
      regs.set_s(x.sd, vfp::to_integer(regs.d[x.m], x.is_signed, x.fpscr_rounding ? c.rounding() : x.rounding, c));
      break;
    default: regs.d[x.d] = double_result(x, regs, c);
  }
  regs.fpscr |= c.flags;
  return VfpOutcome::kExecuted;
}

}  // namespace stepdance::sim::image
