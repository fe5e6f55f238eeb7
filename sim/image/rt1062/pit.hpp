// PIT (Periodic Interrupt Timer, RM chapter 53, registers §53.4): four 32-bit down-counters on
// PERCLK_CLK_ROOT that reload from LDVAL and flag TIF on every expiry.
#pragma once

#include <array>
#include <cstdint>
#include <functional>
#include <memory>

#include "image/chip/chip_context.hpp"
#include "image/chip/peripheral.hpp"
#include "image/rt1062/ccm.hpp"
#include "image/rt1062/register_bits.hpp"
#include "image/rt1062/tick_clock.hpp"

namespace stepdance::sim::image::rt1062 {

/// The PIT at 0x40084000 (gate CCGR1 CG6, RM §14.7.22). MCR (reset 0x2: MDIS set, timers
/// stopped), per channel LDVAL, CVAL (read only), TCTRL (TEN, TIE), TFLG (TIF, write 1 to clear).
/// A running channel counts LDVAL..0 at PERCLK, so it expires every LDVAL + 1 ticks; a new LDVAL
/// takes effect at the next reload (RM §53.5.1). Expiries are scheduled events; the one IRQ (122)
/// is high while any channel has TIF and TIE. Every expiry also pulses the channel's PIT_TRIGGERn
/// output (XBAR1 inputs 56–59, RM chapter 4), whether or not TIE is set. Not modelled (refused as unmodelled): chained
/// channels (TCTRL CHN) and the lifetime timer LTMR64H/L.
class Pit : public Peripheral {
 public:
  Pit(ChipContext& context, Ccm& ccm);
  ~Pit() override;

  const char* name() const override { return "PIT"; }
  uint32_t base() const override { return 0x40084000u; }  // RM table 2-2
  uint32_t size_bytes() const override { return 0x4000u; }
  ClockGate gate() const override { return ClockGate{1, 6}; }
  Access read(uint32_t offset, uint8_t bytes, uint32_t& value) override;
  Access write(uint32_t offset, uint8_t bytes, uint32_t value) override;

  /// Where the PIT_TRIGGERn pulses go: called with n at each expiry of channel n, at its time.
  using TriggerSink = std::function<void(unsigned channel)>;
  /// Sets the sink (one; the chip wires it to XBAR1). Context: board construction.
  void set_trigger_sink(TriggerSink sink) { trigger_sink_ = std::move(sink); }

 private:
  struct Channel {
    uint32_t ldval = 0, tctrl = 0, tflg = 0;
    uint32_t period_ldval = 0;  ///< the LDVAL of the period running now
    TickClock clock;            ///< ticks since the channel started (a fixed origin: no drift)
    uint64_t period_start = 0;  ///< the tick the running period began at
    std::unique_ptr<ModelEvent> expiry;
  };
  bool counting(const Channel& channel) const { return !(mcr_ & 2u) && (channel.tctrl & 1u); }
  uint32_t current_value(const Channel& channel) const;
  void start_counting(Channel& channel);
  void schedule_expiry(Channel& channel);
  void expire(size_t index);
  void restart_all();
  Access write_channel(size_t index, uint32_t reg, uint32_t value);
  void update_irq();

  ChipContext& context_;
  Ccm& ccm_;
  uint32_t mcr_ = 0x2u;
  std::array<Channel, 4> channels_;
  bool irq_high_ = false;
  uint32_t perclk_hz_ = 0;  ///< the PERCLK the running periods count
  TriggerSink trigger_sink_;
};

}  // namespace stepdance::sim::image::rt1062
