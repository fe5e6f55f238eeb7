// Time of the CI firmware image: millis(), micros(), delay(), delayMicroseconds(), yield().
//
// SysTick (ARMv7-M ARM §B3.3) counts the core clock down from F_CPU_ACTUAL / 1000 - 1 and raises
// exception 15 on every wrap: one millisecond. micros() adds the cycles the counter has gone down
// since the last wrap. The DWT cycle counter (ARMv7-M ARM §C1.8.8) is started too: the backend and
// delayMicroseconds() count on it. SysTick and PendSV get priority 32, as on a Teensy, so the
// backend's interrupts (priority numbers above 32) never hold up the millisecond count.
#include <Arduino.h>
#include <stdint.h>

#include "stand_in_registers.h"
#include "stand_in_startup.h"
#include "stepdance/platform/teensy/regs_dwt.hpp"

namespace {

using stand_in::reg32;
namespace systick = stand_in::systick;
namespace dwt = stepdance::platform::teensy::regs::dwt;

volatile uint32_t milliseconds = 0;
uint32_t cycles_per_microsecond = 600;
uint32_t cycles_per_millisecond = 600000;

constexpr uint32_t kSysTickAndPendSvPriority32 = 0x20200000u;  // SHPR3: SysTick 31:24, PendSV 23:16

}  // namespace

extern "C" void stand_in_systick_isr() { milliseconds = milliseconds + 1; }

extern "C" STAND_IN_FLASH void stand_in_systick_start() {
  cycles_per_microsecond = F_CPU_ACTUAL / 1000000u;
  cycles_per_millisecond = F_CPU_ACTUAL / 1000u;
  reg32(systick::kCsr) = 0;
  reg32(systick::kRvr) = cycles_per_millisecond - 1;  // 599999 at 600 MHz: fits the 24-bit reload
  reg32(systick::kCvr) = 0;                           // any write clears the counter
  reg32(stand_in::scb::kShpr3) = kSysTickAndPendSvPriority32;
  reg32(systick::kCsr) = systick::kCsrCoreClock | systick::kCsrTickInt | systick::kCsrEnable;
  dwt::demcr() |= dwt::kDemcrTraceEnable;
  dwt::lar() = dwt::kLarUnlockKey;
  dwt::ctrl() |= dwt::kCtrlCycleCounterEnable;
}

extern "C" {

uint32_t millis() { return milliseconds; }

// Context: any. Where SysTick cannot run (interrupts masked, or a handler of higher priority),
// a wrap not yet counted shows as SysTick pending in ICSR: it is counted here if the counter value
// read is from after that wrap (little time gone since the reload).
uint32_t micros() {
  uint32_t ms;
  uint32_t counter;
  bool pending;
  do {
    ms = milliseconds;
    counter = reg32(systick::kCvr);
    pending = (reg32(stand_in::scb::kIcsr) & stand_in::scb::kIcsrPendSysTick) != 0;
  } while (ms != milliseconds);
  const uint32_t elapsed_cycles = (cycles_per_millisecond - 1u) - counter;
  if (pending && elapsed_cycles < cycles_per_millisecond / 2) ++ms;
  return ms * 1000u + elapsed_cycles / cycles_per_microsecond;
}

// Context: thread mode (SysTick must be able to run). Calls yield() while it waits.
void delay(uint32_t ms) {
  uint32_t start_us = micros();
  while (ms > 0) {
    yield();
    while (ms > 0 && micros() - start_us >= 1000u) {
      --ms;
      start_us += 1000u;
    }
  }
}

// Context: any; counts DWT cycles, so it also works with interrupts masked. Calls yield().
void delayMicroseconds(uint32_t us) {
  const uint32_t start = dwt::cyccnt();
  const uint64_t cycles = static_cast<uint64_t>(us) * cycles_per_microsecond;
  uint64_t waited = 0;
  uint32_t last = start;
  while (waited < cycles) {
    yield();
    const uint32_t now = dwt::cyccnt();
    waited += now - last;
    last = now;
  }
}

/// Nothing to do between loop() passes: no serial events, no background tasks. A sketch may define
/// its own (weak, as in Teensyduino).
__attribute__((weak)) void yield() {}

}  // extern "C"
