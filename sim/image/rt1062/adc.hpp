// ADC1/ADC2 (RM chapter 66, registers §66.8): software-triggered conversions of the pads' analog
// levels, hardware averaging, calibration, the conversion-complete interrupt.
#pragma once

#include <array>
#include <cstdint>

#include "image/chip/board_io.hpp"
#include "image/chip/chip_context.hpp"
#include "image/chip/peripheral.hpp"
#include "image/rt1062/ccm.hpp"
#include "image/rt1062/register_bits.hpp"
#include "image/rt1062/teensy_pins.hpp"
#include "image/rt1062/tick_clock.hpp"

namespace stepdance::sim::image::rt1062 {

/// ADC`module + 1` (module 0 = ADC1 at 0x400C4000, 1 = ADC2 at 0x400C8000; gates CCGR1 CG8 / CG4).
///
/// A write of HC0 with ADCH 0..15 (software trigger) starts a conversion; it ends after the
/// time the manual's formula gives (RM §66.5.4.5, "Conversion time"):
///   SFCAdder + AverageNum × (BCT + LSTAdder + HSCAdder) ADCK cycles, with
///   SFCAdder 6; AverageNum 1 (AVGE 0) or 4/8/16/32 (AVGS); BCT 17/21/25 for 8/10/12 bits (MODE);
///   LSTAdder 3/5/7/9 (ADLSMP 0) or 13/17/21/25 (ADLSMP 1) by ADSTS; HSCAdder 2 when ADHSC;
///   ADCK = (IPG, IPG/2, –, ADACK) ÷ 2^ADIV, ADACK 10 MHz (20 MHz with ADHSC).
/// (The adders are those of this ADC's family documentation, the Vybrid VF6xx/i.MX ADC; SFCAdder
/// and the ADACK frequencies are not re-checked against the RT1060 tables in this session.)
/// Then R0 = BoardIo::analog_level of the pad's Teensy pin at that time, scaled from 0..1023 to
/// the resolution, COCO0 sets, and the IRQ (ADC1 = 67, ADC2 = 68) is high while COCO0 and AIEN.
/// Reading R0 clears COCO0. GC.ADCO repeats conversions (each AverageNum × (…) long). A result
/// finding COCO0 still set is dropped unless CFG.OVWREN. GC.CAL runs a calibration as long as a
/// 32-sample conversion at the settings then (a modelling choice: the RM gives no figure); it
/// ends with CAL clear, CALF clear (it always succeeds) and COCO0 set. Refused as unmodelled: hardware triggers
/// (CFG.ADTRG), HC1..7 conversions, channels whose pad is not a Teensy pin or that are internal
/// (16..30), the compare function (GC.ACFE).
class Adc : public Peripheral {
 public:
  Adc(unsigned module, ChipContext& context, Ccm& ccm, BoardIo& world, TeensyModel model);
  ~Adc() override;

  const char* name() const override { return module_ == 0 ? "ADC1" : "ADC2"; }
  uint32_t base() const override { return 0x400C4000u + 0x4000u * module_; }  // RM table 2-2
  uint32_t size_bytes() const override { return 0x4000u; }
  ClockGate gate() const override { return module_ == 0 ? ClockGate{1, 8} : ClockGate{1, 4}; }
  Access read(uint32_t offset, uint8_t bytes, uint32_t& value) override;
  Access write(uint32_t offset, uint8_t bytes, uint32_t value) override;

  /// The ADCK frequency the CFG settings select now, Hz.
  uint32_t adck_hz() const;
  /// The ADCK cycles of a conversion (first: with SFCAdder) at the CFG/GC settings now.
  uint32_t conversion_cycles(bool first, bool calibration = false) const;

 private:
  enum class Job : uint8_t { kNone, kConversion, kCalibration };
  void start(Job job, bool first);
  void finish();
  Access write_hc0(uint32_t value);
  Access write_cfg(uint32_t value);
  Access write_gc(uint32_t value);
  void update_irq();

  unsigned module_;
  ChipContext& context_;
  Ccm& ccm_;
  BoardIo& world_;
  TeensyModel model_;
  std::array<uint32_t, 8> hc_{};
  uint32_t hs_ = 0, r0_ = 0, cfg_ = 0x200u, gc_ = 0, gs_ = 0, cv_ = 0, ofs_ = 0, cal_ = 0;
  Job job_ = Job::kNone;
  TickClock adck_;          ///< ADCK from the first conversion of a run (continuous runs: no drift)
  uint64_t end_cycle_ = 0;  ///< the ADCK cycle the job in progress ends at
  bool irq_high_ = false;
  ModelEvent done_;
};

}  // namespace stepdance::sim::image::rt1062
