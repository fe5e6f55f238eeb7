// GPT1/GPT2 (General Purpose Timer, RM chapter 52, registers §52.7): a 32-bit up-counter with
// three output compares, in restart or free-run mode, interrupts on compare and rollover.
#pragma once

#include <array>
#include <cstdint>

#include "image/chip/chip_context.hpp"
#include "image/chip/peripheral.hpp"
#include "image/rt1062/ccm.hpp"
#include "image/rt1062/register_bits.hpp"
#include "image/rt1062/tick_clock.hpp"

namespace stepdance::sim::image::rt1062 {

/// GPT`number` (1 or 2). The counter is derived from simulated time and its clock (CLKSRC 1 =
/// PERCLK_CLK_ROOT, 4 = the 32.768 kHz clock, 5 = the 24 MHz oscillator ÷ PRESCALER24M + 1 when
/// EN_24M; then ÷ PRESCALER + 1); other sources (2 high-frequency reference, 3 external) are
/// refused as unmodelled when the timer is enabled with them. Compare and rollover flags are set
/// by scheduled events at their tick's time; the IRQ (GPT1 = 100, GPT2 = 101) is high while
/// SR & IR has a bit. Restart mode (FRR = 0): the counter restarts after OCR1, and a write to
/// OCR1 restarts it (RM §52.5.1 "Restart mode"). Input captures are not modelled (ICRn read 0,
/// IMn must stay 0). Not modelled: the FOn force bits, the output pins (OMn must stay 0).
class Gpt : public Peripheral {
 public:
  Gpt(unsigned number, ChipContext& context, Ccm& ccm);
  ~Gpt() override;

  const char* name() const override { return number_ == 1 ? "GPT1" : "GPT2"; }
  uint32_t base() const override { return number_ == 1 ? 0x401EC000u : 0x401F0000u; }  // RM table 2-2
  uint32_t size_bytes() const override { return 0x4000u; }
  /// The bus gate: GPT1 CCGR1 CG10, GPT2 CCGR0 CG12 (RM §14.7.21/22). The serial gates (CCGR1
  /// CG11, CCGR0 CG13) are not checked: the bus takes one gate per block.
  ClockGate gate() const override { return number_ == 1 ? ClockGate{1, 10} : ClockGate{0, 12}; }
  Access read(uint32_t offset, uint8_t bytes, uint32_t& value) override;
  Access write(uint32_t offset, uint8_t bytes, uint32_t value) override;

  /// The counter (CNT) now.
  uint32_t count_now() const;
  /// The time of the next compare/rollover event, or -1 if none is scheduled.
  SimTime next_event_ns() const { return event_.scheduled() ? event_.time() : -1; }

 private:
  bool enabled() const { return cr_ & 1u; }
  bool restart_mode() const { return !(cr_ & (1u << 9)); }
  uint64_t period_ticks() const;
  uint64_t ticks_now() const;
  Access write_cr(uint32_t value);
  void restart_clock(uint64_t count_at_now);
  void schedule_next();
  void fire();
  void update_irq();

  unsigned number_;
  ChipContext& context_;
  Ccm& ccm_;
  uint32_t cr_ = 0, pr_ = 0, sr_ = 0, ir_ = 0;
  std::array<uint32_t, 3> ocr_{0xFFFFFFFFu, 0xFFFFFFFFu, 0xFFFFFFFFu};
  TickClock clock_;
  uint64_t count_origin_ = 0;   ///< the (unwrapped) count at the clock's origin
  uint64_t handled_tick_ = 0;   ///< the last tick whose compares are flagged
  uint64_t event_tick_ = 0;     ///< the tick the pending event stands for
  uint32_t stopped_count_ = 0;  ///< CNT while disabled
  bool irq_high_ = false;
  uint32_t perclk_hz_ = 0;
  ModelEvent event_;
};

}  // namespace stepdance::sim::image::rt1062
