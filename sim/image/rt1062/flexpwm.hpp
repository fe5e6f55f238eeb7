// eFlexPWM1..4 as Teensyduino's startup (pwm_init) and our input capture (input_capture.cpp) use
// them: free-running submodule counters on the IPG clock, reload flags, and input capture.
// RM chapter 55 (eFlexPWM), registers §55.8 (all 16 bits wide).
#pragma once

#include <cstdint>

#include "image/chip/chip_context.hpp"
#include "image/chip/peripheral.hpp"
#include "image/chip/peripheral_bus.hpp"
#include "image/rt1062/clock_domain.hpp"
#include "kernel/scheduler/event.hpp"

namespace stepdance::sim::image {

/// One eFlexPWM module (PWM1..PWM4), 16-bit accesses only.
///
/// Modelled: each submodule's counter (IPG clock, CLK_SEL 0, ÷2^PRSC) counts INIT..VAL1 and
/// reloads, from RUN on, with the buffered INIT/VAL1/PRSC loaded at RUN or, with LDOK set, at the
/// next full-cycle reload (CTRL FULL); STS RF at every reload and CMPFn when the counter equals
/// VALn (both evaluated from time); the capture circuits of channels A, B and X (CAPTCTRLx ARM,
/// ONESHOT, EDGx0/EDGx1; circuits 0 and 1 alternate in free-running mode; one-word FIFOs whose
/// CVALn read pops them; CVALnCYC = the reload count mod 16 at the capture); the submodule
/// interrupts for capture and reload flags. Other registers (VALn, OCTRL, DTCNTn, DISMAPn, the
/// fault registers, …) are stored as written, because the PWM outputs are not modelled.
/// Refused as kUnmodelled: non-16-bit accesses, reserved offsets, a counter clock other than IPG,
/// load frequencies other than every opportunity, and compare, reload-error or DMA interrupts.
class FlexPwm final : public Peripheral {
 public:
  static constexpr unsigned kSubmodules = 4;

  /// `module` 1..4. Context: board construction.
  FlexPwm(unsigned module, const PeripheralBus& bus, ChipContext& chip);
  ~FlexPwm() override;
  FlexPwm(const FlexPwm&) = delete;
  FlexPwm& operator=(const FlexPwm&) = delete;

  const char* name() const override;
  uint32_t base() const override;
  uint32_t size_bytes() const override { return 0x4000u; }
  /// CCM_CCGR4 CG8..CG11 = pwm1..pwm4 (RM §14.7.25).
  ClockGate gate() const override { return {4, static_cast<int8_t>(7 + module_)}; }
  Access read(uint32_t offset, uint8_t bytes, uint32_t& value) override;
  Access write(uint32_t offset, uint8_t bytes, uint32_t value) override;

  /// An edge at `time_ns` (≤ now) on the capture input of submodule `sm`, channel 0 = A, 1 = B,
  /// 2 = X: captures as the armed circuit selects, sets its flag and updates the interrupt line.
  /// Context: a scheduler event or the lead's pulse delivery (simulator thread).
  void capture_edge(unsigned sm, unsigned channel, bool rising, SimTime time_ns);
  /// The NVIC line of submodule `sm` (RM §4.3 table 4-2). Context: any.
  unsigned irq(unsigned sm) const;

 private:
  /// A running counter: ticks at hz from start, counting init..init + period - 1.
  struct Timebase {
    ClockDomain clock;
    uint16_t init = 0;
    uint32_t period = 0x10000u;
    uint64_t reloads_before = 0;  // reloads counted by earlier timebases
  };
  struct Channel {
    uint16_t ctrl = 0;       // CAPTCTRLx without the FIFO counts
    uint16_t value[2] = {};  // CVAL (circuit 0, 1)
    uint16_t cycle[2] = {};  // CVALnCYC
    bool full[2] = {};       // one-word FIFO
    uint8_t next = 0;        // the circuit armed next in free-running mode
  };
  struct Submodule {
    uint16_t regs[0x30] = {};  // storage by offset / 2
    bool running = false;
    Timebase base;
    bool load_pending = false;  // LDOK set while running: load at this reload
    SimTime load_at_ns = 0;
    uint16_t held_count = 0;                                 // CNT while stopped
    uint16_t sts = 0;                                        // capture flags (RF and CMPF are evaluated from time)
    uint64_t rf_cleared_at = 0;                              // reload count when RF was last cleared
    int64_t cmp_cleared_tick[6] = {-1, -1, -1, -1, -1, -1};  // tick of the last CMPFn clear
    Channel channel[3];                                      // A, B, X
  };
  struct Wake : Event {
    Wake() : Event(&fire) {}
    static void fire(Event& event, Scheduler& scheduler);
    FlexPwm* owner = nullptr;
    unsigned sm = 0;
  };

  // ---- registers (flexpwm.cpp) ----
  Access read_submodule(unsigned sm, uint32_t offset, uint32_t& value);
  Access write_submodule(unsigned sm, uint32_t offset, uint16_t value);
  Access write_mctrl(uint16_t value);
  Access write_captctrl(unsigned sm, unsigned channel, uint16_t value);
  uint16_t read_captctrl(const Channel& channel) const;
  // ---- counters, flags, interrupts (flexpwm_counter.cpp) ----
  bool start(unsigned sm, SimTime now_ns);
  void stop(unsigned sm, SimTime now_ns);
  void refresh(unsigned sm, SimTime now_ns);
  Timebase load(unsigned sm, SimTime start_ns, uint64_t reloads_before) const;
  int64_t ticks(const Submodule& s, SimTime t) const;
  uint16_t counter(const Submodule& s, SimTime t) const;
  uint64_t reloads(const Submodule& s, SimTime t) const;
  SimTime next_reload_ns(const Submodule& s, SimTime t) const;
  uint16_t status(unsigned sm, SimTime now_ns);
  void clear_status(unsigned sm, uint16_t bits, SimTime now_ns);
  uint16_t compare_flags(const Submodule& s, SimTime t) const;
  void settle(unsigned sm);

  unsigned module_;
  const PeripheralBus& bus_;
  ChipContext& chip_;
  Submodule sm_[kSubmodules];
  uint16_t module_regs_[11] = {};  // OUTEN … FCTRL20 (0x180..0x194), MCTRL kept here too
  bool irq_high_[kSubmodules] = {};
  Wake wake_[kSubmodules];
};

}  // namespace stepdance::sim::image
