// SNVS (Secure Non-Volatile Storage, RM chapter 20, registers §20.3): the real-time clocks —
// the low-power secure RTC (SRTC) and the high-power RTC synchronised from it.
#pragma once

#include <cstdint>

#include "image/chip/chip_context.hpp"
#include "image/chip/peripheral.hpp"

namespace stepdance::sim::image::rt1062 {

/// SNVS at 0x400D4000 (gate CCGR5 CG14 "snvs_hp", RM §14.7.26). Both RTCs are 47-bit counters
/// of the 32.768 kHz clock, read as MR (bits 14:0 = count bits 46:32) and LR (count bits 31:0).
/// The SRTC runs while LPCR.SRTC_ENV (bit 0); the HP RTC while HPCR.RTC_EN (bit 0), and
/// HPCR.HP_TS (bit 16, self-clearing) copies the SRTC into it. At reset neither runs and both
/// read 0 (no coin cell: the simulation starts from a cold chip). Modelled: HPCR, HPSR,
/// HPRTCMR/LR, LPCR, LPSR, LPSRTCMR/LR; everything else of SNVS is unmodelled.
class Snvs : public Peripheral {
 public:
  explicit Snvs(ChipContext& context) : context_(context) {}
  const char* name() const override { return "SNVS"; }
  uint32_t base() const override { return 0x400D4000u; }  // RM table 2-2
  uint32_t size_bytes() const override { return 0x4000u; }
  ClockGate gate() const override { return ClockGate{5, 14}; }
  Access read(uint32_t offset, uint8_t bytes, uint32_t& value) override;
  Access write(uint32_t offset, uint8_t bytes, uint32_t value) override;

  /// The SRTC's count now (32.768 kHz ticks).
  uint64_t srtc_count() const { return srtc_.now(context_.now_ns()); }

 private:
  /// A 47-bit counter of the 32.768 kHz clock that runs from `origin_ns` at `value` when `running`.
  struct Counter {
    bool running = false;
    uint64_t value = 0;
    SimTime origin_ns = 0;
    uint64_t now(SimTime time_ns) const;
    void set_running(bool run, SimTime time_ns);
    void set(uint64_t count, SimTime time_ns);
  };
  bool read_word(uint32_t word, uint32_t& value) const;
  bool write_word(uint32_t word, uint32_t value);

  ChipContext& context_;
  uint32_t hpcr_ = 0;
  uint32_t lpcr_ = 0x20u;  // RM §20.3.1.15 reset value (from memory; not checked this session)
  Counter hp_, srtc_;
};

}  // namespace stepdance::sim::image::rt1062
