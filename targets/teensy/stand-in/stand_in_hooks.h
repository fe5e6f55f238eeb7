// What the stand-in core's start-up offers its other parts, the USB serial driver above all.
//
// The start-up (startup.cpp) brings the chip up in this order, each step ending in a marker function
// a debugger or the simulator can break on (stand_in_startup.h lists them). The USB serial driver
// (usb_serial.cpp) hooks in through the two functions below; both have C linkage.
//
// Memory the driver may use: DTCM (ordinary variables: .data/.bss) is not cached, so the USB
// controller's DMA sees it as the core does. OCRAM (0x20200000, the `.dmabuffers` section) is
// write-back cached by the MPU set-up: a driver that puts DMA descriptors or buffers there must clean
// and invalidate the data cache itself (ARMv7-M ARM §B2.2.7, DCCMVAC/DCIMVAC).
#pragma once

#ifdef __cplusplus
extern "C" {
#endif

/// Brings the USB1 PLL (PLL3, CCM_ANALOG_PLL_USB1) up to 480 MHz with its USB clock outputs on,
/// from whatever state it is in; returns once it is locked and out of bypass. Idempotent.
/// The start-up calls it once, before the ARM clock switch (FlexIO2/3 clock from PLL3 too).
/// Context: thread mode, any time after reset.
void stand_in_usb_pll_start(void);

/// Starts the USB serial device. Called once by the start-up after the clocks (600 MHz core,
/// 150 MHz bus, PLL3 at 480 MHz), SysTick (millis/micros) and interrupts are running, before the
/// C++ constructors and setup(). The stand-in's default does nothing (a weak definition); the USB
/// serial driver defines the real one. Context: thread mode, interrupts enabled.
void stand_in_usb_serial_start(void);

#ifdef __cplusplus
}
#endif
