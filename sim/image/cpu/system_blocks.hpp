// The Cortex-M7's own registers in the system space (0xE0000000–0xE00FFFFF, DDI 0403E B3.1
// "the system address map"): each block a Peripheral on the chip's system bus, sharing the
// NVIC state (ExceptionState) and CoreRegisters. Every register not listed is unmodelled.
#pragma once

#include <cstdint>

#include "image/chip/peripheral.hpp"
#include "image/chip/peripheral_bus.hpp"
#include "image/cpu/core_registers.hpp"
#include "image/cpu/exception_state.hpp"
#include "kernel/scheduler/event.hpp"

namespace stepdance::sim::image {

class ImageChip;

/// ICTR and ACTLR (0xE000E000; B3.2.3, B3.2.4).
class ScsBlock : public Peripheral {
 public:
  explicit ScsBlock(CoreRegisters& core) : core_(core) {}
  const char* name() const override { return "SCS"; }
  uint32_t base() const override { return 0xE000E000; }
  uint32_t size_bytes() const override { return 0x10; }
  Access read(uint32_t offset, uint8_t bytes, uint32_t& value) override;
  Access write(uint32_t offset, uint8_t bytes, uint32_t value) override;

 private:
  CoreRegisters& core_;
};

/// SysTick (0xE000E010; B3.3). Clock: CSR.CLKSOURCE = 1 the core clock, 0 the RT1062's external
/// reference, 100 kHz (IMXRT1060RM rev 3, 13.3.1.1 / Teensyduino 1.59 teensy4/startup.c uses it:
/// SYST_RVR = 100000 / 1000 - 1 with CLKSOURCE 0, a 1 kHz tick). Pends exception 15 at each
/// count to zero with CSR.TICKINT, as a scheduler event at that tick's time.
class SysTickBlock : public Peripheral {
 public:
  static constexpr SimTime kExternalTickNs = 10 * kMicrosecond;  ///< 100 kHz reference

  explicit SysTickBlock(ImageChip& chip);
  ~SysTickBlock() override;
  const char* name() const override { return "SysTick"; }
  uint32_t base() const override { return 0xE000E010; }
  uint32_t size_bytes() const override { return 0x10; }
  Access read(uint32_t offset, uint8_t bytes, uint32_t& value) override;
  Access write(uint32_t offset, uint8_t bytes, uint32_t value) override;
  /// True while counting with TICKINT: it will interrupt.
  bool ticking() const { return enabled() && (csr_ & 2) != 0; }
  /// The core clock changed: re-time the next zero (core-clock source only).
  void clock_changed();

 private:
  struct ZeroEvent : Event {
    explicit ZeroEvent(SysTickBlock* owner) : Event(&fire), block(owner) {}
    static void fire(Event& event, Scheduler& scheduler);
    SysTickBlock* block;
  };
  bool enabled() const { return (csr_ & 1) != 0; }
  bool core_clocked() const { return (csr_ & 4) != 0; }
  uint64_t tick_now() const;
  SimTime tick_time(uint64_t tick) const;
  uint32_t value_at(uint64_t tick) const;
  uint64_t zeros_through(uint64_t tick) const;
  void anchor(uint32_t value);
  void schedule_next_zero();

  ImageChip& chip_;
  ZeroEvent zero_event_{this};
  uint32_t csr_ = 0;
  uint32_t rvr_ = 0;
  uint32_t frozen_value_ = 0;  ///< CVR while disabled
  uint64_t anchor_tick_ = 0;   ///< tick at which the counter held anchor_value_
  uint32_t anchor_value_ = 0;
  uint64_t flag_zeros_ = 0;  ///< zeros counted when COUNTFLAG was last read
};

/// NVIC (0xE000E100..0xE000E4EF; B3.4): ISER, ICER, ISPR, ICPR, IABR for 160 IRQs, IPR.
class NvicBlock : public Peripheral {
 public:
  explicit NvicBlock(ImageChip& chip, ExceptionState& state) : chip_(chip), state_(state) {}
  const char* name() const override { return "NVIC"; }
  uint32_t base() const override { return 0xE000E100; }
  uint32_t size_bytes() const override { return 0x3F0; }
  Access read(uint32_t offset, uint8_t bytes, uint32_t& value) override;
  Access write(uint32_t offset, uint8_t bytes, uint32_t value) override;

 private:
  ImageChip& chip_;
  ExceptionState& state_;
};

/// SCB (0xE000ED00..0xE000ED8F; B3.2.2 table B3-4): CPUID, ICSR, VTOR, AIRCR, SCR, CCR,
/// SHPR1-3, SHCSR, CFSR, HFSR, MMFAR, BFAR, AFSR, CLIDR/CTR/CCSIDR/CSSELR, CPACR.
class ScbBlock : public Peripheral {
 public:
  ScbBlock(ImageChip& chip, ExceptionState& state, CoreRegisters& core) : chip_(chip), state_(state), core_(core) {}
  const char* name() const override { return "SCB"; }
  uint32_t base() const override { return 0xE000ED00; }
  uint32_t size_bytes() const override { return 0x90; }
  Access read(uint32_t offset, uint8_t bytes, uint32_t& value) override;
  Access write(uint32_t offset, uint8_t bytes, uint32_t value) override;

 private:
  uint32_t icsr() const;
  uint32_t shcsr() const;
  Access write_icsr(uint32_t value);
  Access write_aircr(uint32_t value);
  void write_shcsr(uint32_t value);
  uint32_t read_shpr(uint32_t offset) const;
  void write_shpr(uint32_t offset, uint8_t bytes, uint32_t value);

  ImageChip& chip_;
  ExceptionState& state_;
  CoreRegisters& core_;
};

/// MPU (0xE000ED90..0xE000EDBF; B3.5): TYPE, CTRL, RNR, RBAR, RASR and aliases. Writes are kept;
/// regions are enforced as ImageChip documents (stack guard, whole no-access pages).
class MpuBlock : public Peripheral {
 public:
  explicit MpuBlock(CoreRegisters& core) : core_(core) {}
  const char* name() const override { return "MPU"; }
  uint32_t base() const override { return 0xE000ED90; }
  uint32_t size_bytes() const override { return 0x30; }
  Access read(uint32_t offset, uint8_t bytes, uint32_t& value) override;
  Access write(uint32_t offset, uint8_t bytes, uint32_t value) override;

 private:
  CoreRegisters& core_;
};

/// Core debug (0xE000EDF0; C1.6): DEMCR only (TRCENA gates the DWT).
class DwtBlock;
class DebugBlock : public Peripheral {
 public:
  DebugBlock(CoreRegisters& core, DwtBlock& dwt) : core_(core), dwt_(dwt) {}
  const char* name() const override { return "CoreDebug"; }
  uint32_t base() const override { return 0xE000EDF0; }
  uint32_t size_bytes() const override { return 0x10; }
  Access read(uint32_t offset, uint8_t bytes, uint32_t& value) override;
  Access write(uint32_t offset, uint8_t bytes, uint32_t value) override;

 private:
  CoreRegisters& core_;
  DwtBlock& dwt_;
};

/// STIR, the FPU's FPCCR/FPCAR/FPDSCR/MVFR0-2 and cache maintenance (0xE000EF00..0xE000EF7F;
/// B3.4.3, B3.2.21-23, B4.8 and the Cortex-M7 TRM 3.3.1).
class ScbExtraBlock : public Peripheral {
 public:
  ScbExtraBlock(ImageChip& chip, CoreRegisters& core) : chip_(chip), core_(core) {}
  const char* name() const override { return "SCB_FPU_CACHE"; }
  uint32_t base() const override { return 0xE000EF00; }
  uint32_t size_bytes() const override { return 0x80; }
  Access read(uint32_t offset, uint8_t bytes, uint32_t& value) override;
  Access write(uint32_t offset, uint8_t bytes, uint32_t value) override;

 private:
  ImageChip& chip_;
  CoreRegisters& core_;
};

/// DWT (0xE0001000; C1.8): CTRL and CYCCNT (the core's cycle count while CYCCNTENA and
/// DEMCR.TRCENA are on), LAR (write accepted).
class DwtBlock : public Peripheral {
 public:
  DwtBlock(ImageChip& chip, CoreRegisters& core) : chip_(chip), core_(core) {}
  const char* name() const override { return "DWT"; }
  uint32_t base() const override { return 0xE0001000; }
  uint32_t size_bytes() const override { return 0x1000; }
  Access read(uint32_t offset, uint8_t bytes, uint32_t& value) override;
  Access write(uint32_t offset, uint8_t bytes, uint32_t value) override;
  /// CYCCNT now.
  uint32_t cyccnt() const;
  /// CYCCNT holds `value` now and counts on from here if CYCCNTENA and TRCENA are on.
  void restart_count(uint32_t value);

 private:
  ImageChip& chip_;
  CoreRegisters& core_;
};

/// All of them, added to one bus.
class SystemBlocks {
 public:
  SystemBlocks(ImageChip& chip, ExceptionState& state, CoreRegisters& core);
  void add_to(PeripheralBus& bus);
  SysTickBlock& systick() { return systick_; }

 private:
  ScsBlock scs_;
  SysTickBlock systick_;
  NvicBlock nvic_;
  ScbBlock scb_;
  MpuBlock mpu_;
  DebugBlock debug_;
  ScbExtraBlock extra_;
  DwtBlock dwt_;
};

}  // namespace stepdance::sim::image
