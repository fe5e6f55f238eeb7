// ENC1/ENC2 quadrature decoders as the backend's quadrature.cpp uses them: a free 32-bit position
// counter fed by the knob's A/B phases through XBAR1. RM chapter 56 (ENC), registers §56.8.
#pragma once

#include <cstdint>

#include "image/chip/board_io.hpp"
#include "image/chip/chip_context.hpp"
#include "image/chip/peripheral.hpp"
#include "image/chip/peripheral_bus.hpp"
#include "image/rt1062/xbar1.hpp"

namespace stepdance::sim::image {

/// ENCn (n = 1, 2), 16-bit registers. The position counts BoardIo::encoder_counts(n - 1) while
/// both phase inputs are routed to the encoder pins (XBAR1 outputs ENCn PHASEA/B select the pads'
/// XBAR1_INOUT inputs, and, if an IOMUXC answers on the bus, the pads are in that ALT with the
/// input select and GPR6 direction set: quadrature.cpp's wiring); SWIP loads UINIT/LINIT; CTRL
/// REV reverses the count. Reading POSD, REV, UPOS or LPOS latches all four into their hold
/// registers and clears POSD (RM §56.3, "holding registers"); with CTRL2 UPDHLD, so does a rising
/// edge on the TRIGGER input (XBAR1 output 70 / 75; trigger()). Refused (kUnmodelled): interrupt
/// enables, single-phase mode, modulus counting and the other CTRL2 modes, TST, IMR, writes of
/// the position registers.
class Enc final : public Peripheral {
 public:
  /// `index` 0 = ENC1, 1 = ENC2. Context: board construction.
  Enc(unsigned index, const PeripheralBus& bus, ChipContext& chip, BoardIo& io, const Xbar1& xbar);

  const char* name() const override { return index_ == 0 ? "ENC1" : "ENC2"; }
  uint32_t base() const override { return 0x403C8000u + 0x4000u * index_; }  // RM §2.3
  uint32_t size_bytes() const override { return 0x4000u; }
  ClockGate gate() const override { return {4, static_cast<int8_t>(12 + index_)}; }  // CCGR4 CG12/CG13
  Access read(uint32_t offset, uint8_t bytes, uint32_t& value) override;
  Access write(uint32_t offset, uint8_t bytes, uint32_t value) override;

  /// Re-checks the phase routing now (XBAR1 calls it after each SELn write). Context: any.
  void routing_changed();
  /// The 32-bit position now. Context: any.
  uint32_t position();
  /// A rising edge on TRIGGER now: with CTRL2 UPDHLD the hold registers take the position (the
  /// edge is synchronised to the IPG clock on the chip, a few ns; here it is taken at once).
  /// Context: the event that made the edge.
  void trigger();
  /// When a trigger first updated the holds, ns; -1 if none has. Context: any.
  SimTime first_trigger_ns() const { return first_trigger_ns_; }
  /// XBAR1 output that drives this encoder's TRIGGER (RM chapter 4).
  uint8_t trigger_output() const { return index_ == 0 ? 70 : 75; }

 private:
  bool phases_routed() const;
  int64_t counts_now() const;
  void latch_holds();

  unsigned index_;
  const PeripheralBus& bus_;
  ChipContext& chip_;
  BoardIo& io_;
  const Xbar1& xbar_;
  bool routed_ = false;
  int64_t held_ = 0;       // position while not routed (and the base when routing starts)
  int64_t offset_ = 0;     // position = direction × counts + offset while routed
  int64_t posd_base_ = 0;  // position at the last POSD clear
  SimTime first_trigger_ns_ = -1;
  uint16_t ctrl2_ = 0;
  uint16_t ctrl_ = 0, filt_ = 0, wtr_ = 0, uinit_ = 0, linit_ = 0, umod_ = 0, lmod_ = 0;
  uint16_t ucomp_ = 0xFFFFu, lcomp_ = 0xFFFFu;  // reset values (RM §56.8)
  uint16_t posdh_ = 0, revh_ = 0, uposh_ = 0, lposh_ = 0;
};

}  // namespace stepdance::sim::image
