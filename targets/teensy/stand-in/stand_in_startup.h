// The start-up's steps and markers, shared by the stand-in core's sources (not for sketches).
//
// stand_in_start() (startup.cpp) runs the steps in the order below. After each one it calls an
// empty marker function of the same name with `_ready` (C linkage, never inlined, in flash): a test
// or a debugger that stops at stand_in_clocks_ready knows the clocks are set, and so on. The fault
// handlers park the core in a loop at their own symbol (stand_in_hard_fault, ...).
#pragma once

#include <stdint.h>

/// Start-up code that runs once: kept in flash, out of the 32 KB ITCM banks (as Teensy's FLASHMEM).
#if defined(STEPDANCE_TEENSY_REGISTER_MODEL)
#define STAND_IN_FLASH  // host tests of the stand-in (tests/platform/teensy/stand_in/)
#else
#define STAND_IN_FLASH __attribute__((section(".flashmem.stand_in"), noinline))
#endif

extern "C" {

// ---- Steps (each in its own source file) ------------------------------------------------------
/// Programs the MPU regions and enables the caches (memory_protection.cpp). ARMv7-M ARM §B3.5.
void stand_in_memory_protection_start();
/// DCDC to 1.25 V, ARM PLL to 1200 MHz, core 600 MHz, AHB 600 MHz, IPG 150 MHz; PERCLK 24 MHz;
/// all pins on the fast GPIO6..9; PLL3 at 480 MHz (clocks.cpp). RM §14, DCDC.
void stand_in_clocks_start();
/// SysTick at 1 kHz from the core clock, the DWT cycle counter (systick.cpp). ARMv7-M ARM §B3.3.
void stand_in_systick_start();
/// ADC1 and ADC2: 10-bit, 4-sample averages, calibrated (analog.cpp). RM ADC chapter.
void stand_in_analog_start();
/// The SysTick exception handler (exception 15): one millisecond more.
void stand_in_systick_isr();

// ---- Markers: empty, one per finished step ------------------------------------------------------
void stand_in_memory_ready();             // FlexRAM banks, stack, FPU, .text.itcm/.data copied, .bss zeroed
void stand_in_vectors_ready();            // RAM vector table in VTOR, fault handlers enabled
void stand_in_memory_protection_ready();  // MPU regions on, caches on
void stand_in_clocks_ready();             // 600 MHz / 150 MHz, F_CPU_ACTUAL and F_BUS_ACTUAL set
void stand_in_systick_ready();            // millis()/micros() running, interrupts enabled
void stand_in_analog_ready();             // ADCs calibrated
void stand_in_usb_ready();                // stand_in_usb_serial_start() has returned
void stand_in_constructors_done();        // the C++ constructors have run; main() comes next

// ---- Fault handlers: each parks the core in a loop at its own symbol ------------------------------
void stand_in_hard_fault();
void stand_in_mem_manage_fault();
void stand_in_bus_fault();
void stand_in_usage_fault();
void stand_in_unused_handler();  // every other exception and interrupt nobody attached

/// Nonzero if an ADC reported a failed calibration (GS.CALF) at start-up: bit 0 ADC1, bit 1 ADC2.
extern volatile uint32_t stand_in_adc_calibration_failed;
}
