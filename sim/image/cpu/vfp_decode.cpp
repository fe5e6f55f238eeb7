// Encodings: ARMv7-M ARM A6.4 "floating-point data-processing instructions" (T1/T2 with
// coprocessor field 0b101, sz = bit 8) and the FPv5 instructions of ARMv8-M (VSEL, VMAXNM,
// VMINNM, VRINT{A,N,P,M}, VCVT{A,N,P,M}: first halfword 0xFExx). FPv5-D16 has D0–D15 only: a
// double register with its top bit (D, N or M) set is undefined, and not decoded here.
#include "image/cpu/vfp_decode.hpp"

#include "image/cpu/vfp_arith.hpp"

namespace stepdance::sim::image::vfp {
namespace {

struct Fields {
  uint32_t word;
  unsigned opc1() const { return ((word >> 20) & 0xB); }  // bits 23,21,20 (22 is D)
  unsigned opc2() const { return (word >> 16) & 0xF; }
  bool bit7() const { return (word >> 7) & 1; }
  bool bit6() const { return (word >> 6) & 1; }
  unsigned vd() const { return (word >> 12) & 0xF; }
  unsigned vn() const { return (word >> 16) & 0xF; }
  unsigned vm() const { return word & 0xF; }
  bool high_d() const { return (word >> 22) & 1; }
  bool high_n() const { return (word >> 7) & 1; }
  bool high_m() const { return (word >> 5) & 1; }
  bool double_size() const { return (word >> 8) & 1; }
  uint8_t single_d() const { return static_cast<uint8_t>(vd() << 1 | high_d()); }
  uint8_t single_m() const { return static_cast<uint8_t>(vm() << 1 | high_m()); }
};

Decoded three_register(const Fields& f, Op op) {
  Decoded decoded;
  if (f.high_d() || f.high_n() || f.high_m()) return decoded;
  decoded.op = op;
  decoded.d = static_cast<uint8_t>(f.vd());
  decoded.n = static_cast<uint8_t>(f.vn());
  decoded.m = static_cast<uint8_t>(f.vm());
  return decoded;
}

// Dd and Dm as double registers; a single-register side given by `single_d`/`single_m`.
Decoded two_register(const Fields& f, Op op, bool single_d = false, bool single_m = false) {
  Decoded decoded;
  if ((!single_d && f.high_d()) || (!single_m && f.high_m())) return decoded;
  decoded.op = op;
  decoded.d = static_cast<uint8_t>(f.vd());
  decoded.m = static_cast<uint8_t>(f.vm());
  decoded.sd = f.single_d();
  decoded.sm = f.single_m();
  return decoded;
}

// opc1 = 1x11, opc3 = x1 (A6.4 table "other data-processing"): by opc2. sz = 1 except VCVT.F64.F32.
Decoded other(const Fields& f) {
  const bool b7 = f.bit7();
  switch (f.opc2()) {
    case 0x0: return two_register(f, b7 ? Op::kVabs : Op::kVmov);
    case 0x1: return two_register(f, b7 ? Op::kVsqrt : Op::kVneg);
    case 0x4: return two_register(f, b7 ? Op::kVcmpe : Op::kVcmp);
    case 0x5: return (f.word & 0x2F) == 0 ? two_register(f, b7 ? Op::kVcmpeZero : Op::kVcmpZero) : Decoded{};
    case 0x6: {
      Decoded decoded = two_register(f, Op::kVrint);
      decoded.rounding = b7 ? uint8_t{kZero} : uint8_t{kNearest};
      decoded.fpscr_rounding = !b7;
      return decoded;
    }
    case 0x7: {
      if (!b7) {
        Decoded decoded = two_register(f, Op::kVrint);
        decoded.fpscr_rounding = decoded.exact = true;
        return decoded;
      }
      return f.double_size() ? two_register(f, Op::kVcvtF32F64, true, false) : two_register(f, Op::kVcvtF64F32, false, true);
    }
    case 0x8: {
      Decoded decoded = two_register(f, Op::kVcvtIntF64, false, true);
      decoded.is_signed = b7;
      return decoded;
    }
    case 0xC:
    case 0xD: {
      Decoded decoded = two_register(f, Op::kVcvtF64Int, true, false);
      decoded.is_signed = (f.opc2() & 1) != 0;
      decoded.rounding = kZero;
      decoded.fpscr_rounding = !b7;
      return decoded;
    }
    default: return {};  // half precision, fixed point: not decoded
  }
}

Decoded conditional(const Fields& f) {
  const bool op = f.bit6();
  switch (f.opc1()) {
    case 0x0: return three_register(f, op ? Op::kVmls : Op::kVmla);
    case 0x1: return three_register(f, op ? Op::kVnmla : Op::kVnmls);
    case 0x2: return three_register(f, op ? Op::kVnmul : Op::kVmul);
    case 0x3: return three_register(f, op ? Op::kVsub : Op::kVadd);
    case 0x8: return op ? Decoded{} : three_register(f, Op::kVdiv);
    case 0x9: return three_register(f, op ? Op::kVfnma : Op::kVfnms);
    case 0xA: return three_register(f, op ? Op::kVfms : Op::kVfma);
    case 0xB: break;
    default: return {};
  }
  if (op) return other(f);
  if ((f.word & 0xA0) != 0 || f.high_d()) return {};  // VMOV immediate: bits 7 and 5 are (0)
  Decoded decoded;
  decoded.op = Op::kVmovImmediate;
  decoded.d = static_cast<uint8_t>(f.vd());
  decoded.immediate = static_cast<uint8_t>((f.opc2() << 4) | f.vm());
  return decoded;
}

// 0xFE: VSEL (opc1 0xxx), VMAXNM/VMINNM (1x00), VRINT{A,N,P,M} (1x11 opc2 10RM, opc3 01),
// VCVT{A,N,P,M} (1x11 opc2 11RM, opc3 x1).
Decoded unconditional(const Fields& f) {
  static constexpr uint8_t kDirected[4] = {kAway, kNearest, kPlusInf, kMinusInf};
  if ((f.word & (1u << 23)) == 0) {
    Decoded decoded = three_register(f, Op::kVsel);
    decoded.condition = static_cast<uint8_t>((f.word >> 20) & 3);
    return decoded.op == Op::kNone || f.bit6() ? Decoded{} : decoded;
  }
  if (f.opc1() == 0x8) return three_register(f, f.bit6() ? Op::kVminnm : Op::kVmaxnm);
  if (f.opc1() != 0xB || !f.bit6() || f.double_size() == false) return {};
  const unsigned opc2 = f.opc2();
  Decoded decoded;
  if ((opc2 & 0xC) == 0x8 && !f.bit7()) {
    decoded = two_register(f, Op::kVrint);
  } else if ((opc2 & 0xC) == 0xC) {
    decoded = two_register(f, Op::kVcvtF64Int, true, false);
    decoded.is_signed = f.bit7();
  } else {
    return {};
  }
  decoded.rounding = kDirected[opc2 & 3];
  return decoded;
}

}  // namespace

Decoded decode(uint32_t instruction) {
  const Fields f{instruction};
  const unsigned top = instruction >> 24;
  if ((top != 0xEE && top != 0xFE) || ((instruction >> 9) & 7) != 5 || (instruction & 0x10) != 0) return {};
  if (top == 0xFE) return f.double_size() ? unconditional(f) : Decoded{};
  if (!f.double_size()) {
    // Single precision belongs to the emulator, except VCVT.F64.F32 (sz = 0, a double result).
    const bool widen = f.opc1() == 0xB && f.opc2() == 0x7 && (instruction & 0xC0) == 0xC0;
    return widen ? other(f) : Decoded{};
  }
  return conditional(f);
}

}  // namespace stepdance::sim::image::vfp
